// Recorded configurations for animation writers (VTK series, HTML page).
#pragma once

#include <string>
#include <vector>

#include "core/types.hpp"

namespace finseg {

/// What acts on each segment at one output (VTK cell data). Every vector has one entry per
/// body, or is empty when not recorded.
struct SegmentFields {
  std::vector<Vec3> force_W;             ///< resultant force on the segment (everything), N
  std::vector<Vec3> moment_W;            ///< resultant moment about its centroid, N m
  std::vector<double> element_force;     ///< largest |force| among its force elements, N
  std::vector<double> element_moment;    ///< largest |moment| among its force elements, N m
  std::vector<double> crease_opening;    ///< opening angle of a bordering crease, rad; NaN: none
  std::vector<double> crease_moment;     ///< that crease element's law moment, N m; NaN: none
  std::vector<double> contact_normal;    ///< contact normal force on the segment, N
  std::vector<double> contact_friction;  ///< contact friction force magnitudes, N
};

/// One recorded configuration of all bodies.
struct Frame {
  double t = 0;                        ///< time (s) or drive displacement (m) for quasi-static runs
  std::vector<Vec3> p_W;               ///< body centroids, m
  std::vector<Mat3> R_WB;              ///< orientations
  std::vector<Vec3> contact_points_W;  ///< active contact points, m (may be empty)
  std::vector<Vec3> v_W;               ///< centroid velocities, m/s (may be empty)
  std::vector<Vec3> w_W;               ///< angular velocities, world frame, rad/s (with v_W)
  SegmentFields segments;              ///< per-segment loads (may be empty)
  /// Per contact point, parallel to contact_points_W (may be empty): N, m, N.
  std::vector<double> contact_normal, contact_penetration, contact_friction;
};

/// Calls visit(name, std::vector<double>&) for each per-segment and per-contact-point array
/// of a frame, by its name in checkpoints (FrameT: Frame or const Frame).
template <class FrameT, class Visit>
void visit_frame_arrays(FrameT& f, Visit&& visit) {
  auto& s = f.segments;
  visit("segment_element_force_N", s.element_force);
  visit("segment_element_moment_Nm", s.element_moment);
  visit("segment_crease_opening_rad", s.crease_opening);
  visit("segment_crease_moment_Nm", s.crease_moment);
  visit("segment_contact_normal_N", s.contact_normal);
  visit("segment_contact_friction_N", s.contact_friction);
  visit("contact_normal_N", f.contact_normal);
  visit("contact_penetration_m", f.contact_penetration);
  visit("contact_friction_N", f.contact_friction);
}

/// Calls visit(name, std::vector<Vec3>&) for each vector field of a frame (as above).
template <class FrameT, class Visit>
void visit_frame_vectors(FrameT& f, Visit&& visit) {
  visit("p_W_m", f.p_W);
  visit("contact_points_W_m", f.contact_points_W);
  visit("v_W_m_s", f.v_W);
  visit("w_W_rad_s", f.w_W);
  visit("segment_force_W_N", f.segments.force_W);
  visit("segment_moment_W_Nm", f.segments.moment_W);
}

/// An x-y curve shown beside an animation (e.g. gauge force against pull displacement).
struct Curve {
  std::string x_label, y_label;  ///< with units, e.g. "pull displacement [mm]"
  std::vector<double> x, y;      ///< one point per frame, same order as the frames
};

}  // namespace finseg

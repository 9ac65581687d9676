// VTK XML output: one .vtu per frame with a prism cell per segment (wedge, hexahedron,
// pentagonal or hexagonal prism, convex point set beyond), a .pvd collection
// with the frame times, the same pair for contact points when there are any, and mode
// shapes. Arrays are binary, zlib-compressed, appended (writers/vtk_appended.hpp).
#include "writers/vtk.hpp"

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <string>

#include <fmt/format.h>

#include "core/error.hpp"
#include "writers/atomic_write.hpp"
#include "writers/frame_check.hpp"
#include "writers/vtk_appended.hpp"

namespace finseg {
namespace {

constexpr std::uint8_t kVtkVertex = 1;
constexpr std::uint8_t kVtkWedge = 13;
constexpr std::uint8_t kVtkHexahedron = 12;
constexpr std::uint8_t kVtkPentagonalPrism = 15;
constexpr std::uint8_t kVtkHexagonalPrism = 16;
constexpr std::uint8_t kVtkConvexPointSet = 41;

// VTK cell type of a prism over a polygon of n sides.
std::uint8_t prism_cell_type(std::size_t n) {
  switch (n) {
    case 3:
      return kVtkWedge;
    case 4:
      return kVtkHexahedron;
    case 5:
      return kVtkPentagonalPrism;
    case 6:
      return kVtkHexagonalPrism;
    default:
      return kVtkConvexPointSet;
  }
}

// Corners of body b's prism in VTK's node order: its wedge's first triangle faces away from
// the second (clockwise seen from +z), the other prisms' first face towards the second.
std::vector<Vec3> cell_corners_W(const BodyDef& body, const Vec3& p_W, const Mat3& R_WB) {
  Outline o = body.outline_B;
  if (o.size() == 3) std::swap(o[1], o[2]);
  return prism_corners_W(o, body.thickness, p_W, R_WB);
}

const char* kUnitsComment =
    "<!-- finseg: SI units (m, m/s, N, N m, Pa; angles in deg as named); timestep = Frame::t, "
    "time in s, or the drive displacement in m for quasi-static runs (mode files: the mode "
    "number) -->\n";

std::vector<double> flat(const std::vector<Vec3>& v) {
  std::vector<double> out;
  out.reserve(3 * v.size());
  for (const Vec3& x : v) out.insert(out.end(), {x.x(), x.y(), x.z()});
  return out;
}

// Point and cell data of one piece, as DataArray tags already registered with `app`.
struct PieceData {
  std::string point_data, cell_data;
};

// Cells take consecutive points: cell c has sizes[c] of them and VTK type types[c].
std::string vtu(const std::vector<Vec3>& points, const std::vector<std::int64_t>& sizes,
                const std::vector<std::uint8_t>& types, const PieceData& data, VtkAppended& app) {
  const std::size_t cells = sizes.size();
  std::vector<std::int64_t> conn(points.size()), offsets(cells);
  for (std::size_t k = 0; k < conn.size(); ++k) conn[k] = static_cast<std::int64_t>(k);
  std::int64_t end = 0;
  for (std::size_t c = 0; c < cells; ++c) offsets[c] = end += sizes[c];
  std::string out = fmt::format(
      "<?xml version=\"1.0\"?>\n{}"
      "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" "
      "header_type=\"UInt64\" {}>\n"
      "  <UnstructuredGrid>\n"
      "    <Piece NumberOfPoints=\"{}\" NumberOfCells=\"{}\">\n",
      kUnitsComment, kVtkCompressor, points.size(), cells);
  out += "      <PointData>\n" + data.point_data + "      </PointData>\n";
  out += "      <CellData>\n" + data.cell_data + "      </CellData>\n";
  out += "      <Points>\n" + app.array("Float64", "position_m", 3, flat(points)) +
         "      </Points>\n";
  out += "      <Cells>\n" + app.array("Int64", "connectivity", 1, conn) +
         app.array("Int64", "offsets", 1, offsets) + app.array("UInt8", "types", 1, types) +
         "      </Cells>\n";
  out += "    </Piece>\n  </UnstructuredGrid>\n" + app.section() + "</VTKFile>\n";
  return out;
}

template <class F>
std::vector<double> per_body(std::size_t n, F get) {
  std::vector<double> v(n);
  for (std::size_t i = 0; i < n; ++i) v[i] = get(i);
  return v;
}

std::string segment_arrays(const Model& model, const SegmentFields& s, VtkAppended& app) {
  const std::size_t n = model.bodies.size();
  std::string out = app.array("Float64", "force_N", 3, flat(s.force_W)) +
                    app.array("Float64", "moment_Nm", 3, flat(s.moment_W)) +
                    app.array("Float64", "element_force_N", 1, s.element_force) +
                    app.array("Float64", "element_moment_Nm", 1, s.element_moment);
  out += app.array("Float64", "crease_opening_deg", 1,
                   per_body(n, [&](std::size_t i) { return s.crease_opening[i] / kDegToRad; }));
  out += app.array("Float64", "crease_moment_Nm", 1, s.crease_moment) +
         app.array("Float64", "contact_normal_N", 1, s.contact_normal) +
         app.array("Float64", "contact_friction_N", 1, s.contact_friction);
  out += app.array("Float64", "contact_pressure_Pa", 1, per_body(n, [&](std::size_t i) {
                     return s.contact_normal[i] / segment_area(model.bodies[i]);
                   }));
  return out;
}

std::string bodies_vtu(const Model& model, const Frame& frame, const ModeShape* mode) {
  const std::size_t n = model.bodies.size();
  std::vector<Vec3> points, displacement, velocity, shape;
  std::vector<std::int64_t> sizes(n);
  std::vector<std::uint8_t> types(n);
  for (std::size_t b = 0; b < n; ++b) {
    const BodyDef& body = model.bodies[b];
    const std::vector<Vec3> now = cell_corners_W(body, frame.p_W[b], frame.R_WB[b]);
    const std::vector<Vec3> start = cell_corners_W(body, body.p0_W, body.R0_WB);
    sizes[b] = static_cast<std::int64_t>(now.size());
    types[b] = prism_cell_type(body.outline_B.size());
    for (std::size_t c = 0; c < now.size(); ++c) {
      points.push_back(now[c]);
      displacement.push_back(now[c] - start[c]);
      const Vec3 r = now[c] - frame.p_W[b];
      if (!frame.v_W.empty()) velocity.push_back(frame.v_W[b] + frame.w_W[b].cross(r));
      if (mode) shape.push_back(mode->dp_W[b] + mode->dphi_W[b].cross(r));
    }
  }
  VtkAppended app;
  PieceData d;
  d.point_data = app.array("Float64", "displacement_m", 3, flat(displacement));
  if (!velocity.empty()) d.point_data += app.array("Float64", "velocity_m_s", 3, flat(velocity));
  if (mode) d.point_data += app.array("Float64", "mode_shape", 3, flat(shape));
  std::vector<std::int32_t> body(n), panel(n), fixed(n);
  for (std::size_t i = 0; i < n; ++i) {
    body[i] = static_cast<std::int32_t>(i);
    panel[i] = model.bodies[i].panel + 1;  // from 1, as in scene files and the HTML legend
    fixed[i] = model.bodies[i].fixed ? 1 : 0;
  }
  d.cell_data = app.array("Int32", "body", 1, body) + app.array("Int32", "panel", 1, panel) +
                app.array("Int32", "fixed", 1, fixed);
  if (!frame.segments.force_W.empty()) d.cell_data += segment_arrays(model, frame.segments, app);
  return vtu(points, sizes, types, d, app);
}

std::string contacts_vtu(const Frame& frame) {
  VtkAppended app;
  PieceData d;
  if (!frame.contact_normal.empty()) {
    d.point_data = app.array("Float64", "normal_force_N", 1, frame.contact_normal) +
                   app.array("Float64", "penetration_m", 1, frame.contact_penetration) +
                   app.array("Float64", "friction_force_N", 1, frame.contact_friction);
  }
  const std::vector<Vec3>& pts = frame.contact_points_W;
  return vtu(pts, std::vector<std::int64_t>(pts.size(), 1),
             std::vector<std::uint8_t>(pts.size(), kVtkVertex), d, app);
}

std::string pvd(const std::vector<double>& times, const std::vector<std::string>& files) {
  std::string out = "<?xml version=\"1.0\"?>\n";
  out += kUnitsComment;
  out += "<VTKFile type=\"Collection\" version=\"1.0\" byte_order=\"LittleEndian\">\n";
  out += "  <Collection>\n";
  for (std::size_t f = 0; f < times.size(); ++f) {
    out += fmt::format("    <DataSet timestep=\"{:.17g}\" part=\"0\" file=\"{}\"/>\n", times[f],
                       files[f]);
  }
  out += "  </Collection>\n</VTKFile>\n";
  return out;
}

// Optional per-body and per-point arrays must match the frame.
void check_optional_sizes(const Model& model, const std::vector<Frame>& frames) {
  const std::size_t n = model.bodies.size();
  for (std::size_t f = 0; f < frames.size(); ++f) {
    const Frame& fr = frames[f];
    const SegmentFields& s = fr.segments;
    const std::size_t c = fr.contact_points_W.size();
    const bool ok =
        (fr.v_W.empty() || (fr.v_W.size() == n && fr.w_W.size() == n)) &&
        (s.force_W.empty() || (s.force_W.size() == n && s.moment_W.size() == n &&
                               s.element_force.size() == n && s.element_moment.size() == n &&
                               s.crease_opening.size() == n && s.crease_moment.size() == n &&
                               s.contact_normal.size() == n && s.contact_friction.size() == n)) &&
        (fr.contact_normal.empty() ||
         (fr.contact_normal.size() == c && fr.contact_penetration.size() == c &&
          fr.contact_friction.size() == c));
    if (!ok) {
      throw InputError(model.source, "frames[" + std::to_string(f) + "]",
                       "velocity, segment or contact-point arrays do not match the bodies/points");
    }
  }
}

}  // namespace

void write_vtk_series(const std::string& dir, const std::string& stem, const Model& model,
                      const std::vector<Frame>& frames,
                      const std::function<void(double)>& on_progress) {
  check_frames(model, frames);
  check_optional_sizes(model, frames);
  namespace fs = std::filesystem;
  fs::create_directories(dir);
  const fs::path base(dir);

  bool any_contacts = false;
  for (const Frame& f : frames) any_contacts = any_contacts || !f.contact_points_W.empty();

  std::vector<std::string> body_files, contact_files;
  std::vector<double> times;
  for (std::size_t f = 0; f < frames.size(); ++f) {
    const std::string name = fmt::format("{}_{:05d}.vtu", stem, f);
    write_file_atomically((base / name).string(), bodies_vtu(model, frames[f], nullptr));
    body_files.push_back(name);
    times.push_back(frames[f].t);
    if (any_contacts) {
      const std::string cname = fmt::format("{}_contacts_{:05d}.vtu", stem, f);
      write_file_atomically((base / cname).string(), contacts_vtu(frames[f]));
      contact_files.push_back(cname);
    }
    if (on_progress) on_progress(static_cast<double>(f + 1) / static_cast<double>(frames.size()));
  }
  // The collections last: they only ever list files that are complete on disk.
  if (any_contacts) {
    write_file_atomically((base / (stem + "_contacts.pvd")).string(), pvd(times, contact_files));
  }
  write_file_atomically((base / (stem + ".pvd")).string(), pvd(times, body_files));
}

ModeShape mode_shape(const Model& model, const State& state, const Mode& mode) {
  const std::size_t n = model.bodies.size();
  ModeShape m{mode.frequency_hz, std::vector<Vec3>(n, Vec3::Zero()),
              std::vector<Vec3>(n, Vec3::Zero())};
  double largest = 0;
  Vec3 at_largest = Vec3::Zero();
  for (std::size_t b = 0; b < n; ++b) {
    const int d = model.dof_of_body[b];
    if (d < 0) continue;
    m.dp_W[b] = mode.shape.segment<3>(d);
    m.dphi_W[b] = mode.shape.segment<3>(d + 3);
    const BodyDef& body = model.bodies[b];
    for (const Vec3& c :
         prism_corners_W(body.outline_B, body.thickness, state.p_W[b], state.R_WB[b])) {
      const Vec3 u = m.dp_W[b] + m.dphi_W[b].cross(c - state.p_W[b]);
      if (u.norm() > largest) {
        largest = u.norm();
        at_largest = u;
      }
    }
  }
  if (!(largest > 0)) return m;
  Eigen::Index k;
  at_largest.cwiseAbs().maxCoeff(&k);
  const double scale = (at_largest[k] < 0 ? -1.0 : 1.0) / largest;
  for (std::size_t b = 0; b < n; ++b) {
    m.dp_W[b] *= scale;
    m.dphi_W[b] *= scale;
  }
  return m;
}

void write_vtk_modes(const std::string& dir, const std::string& stem, const Model& model,
                     const Frame& equilibrium, const std::vector<ModeShape>& modes) {
  check_frames(model, {equilibrium});
  const std::size_t n = model.bodies.size();
  for (std::size_t m = 0; m < modes.size(); ++m) {
    if (modes[m].dp_W.size() != n || modes[m].dphi_W.size() != n) {
      throw InputError(model.source, "modes[" + std::to_string(m) + "]",
                       "shape does not match the bodies");
    }
  }
  namespace fs = std::filesystem;
  fs::create_directories(dir);
  std::vector<std::string> files;
  std::vector<double> numbers;
  for (std::size_t m = 0; m < modes.size(); ++m) {
    const std::string name = fmt::format("{}_{:05d}.vtu", stem, m + 1);
    write_file_atomically((fs::path(dir) / name).string(),
                          bodies_vtu(model, equilibrium, &modes[m]));
    files.push_back(name);
    numbers.push_back(static_cast<double>(m + 1));
  }
  write_file_atomically((fs::path(dir) / (stem + ".pvd")).string(), pvd(numbers, files));
}

}  // namespace finseg

// fold_text / write_fold (fold_format.hpp): one JSON value per line inside each array, so
// that files of 10^5 edges stay readable and diffable; numbers as nlohmann::json prints
// them (shortest text that reads back to the same double).
#include <nlohmann/json.hpp>
#include <sstream>

#include "patterns/fold_format.hpp"
#include "writers/atomic_write.hpp"

namespace finseg {
namespace {

using nlohmann::json;

template <class Row>
void array_field(std::ostringstream& out, const char* key, std::size_t n, Row row) {
  out << ",\n  \"" << key << "\": [";
  for (std::size_t i = 0; i < n; ++i) out << (i ? ",\n    " : "\n    ") << row(i).dump();
  out << (n ? "\n  ]" : "]");
}

bool has_assignment(const CreasePattern& p, EdgeAssignment a) {
  for (const PatternEdge& e : p.edges) {
    if (e.assignment == a) return true;
  }
  return false;
}

// One file_frames entry classed foldedForm: 3-D coordinates in m on the key frame's mesh.
void folded_frame(std::ostringstream& out, const std::string& title,
                  const std::vector<Vec3>& vertices) {
  out << "{";
  if (!title.empty()) out << "\n  \"frame_title\": " << json(title).dump() << ",";
  out << "\n  \"frame_classes\": [\"foldedForm\"]";
  out << ",\n  \"frame_attributes\": [\"3D\"]";
  out << ",\n  \"frame_parent\": 0,\n  \"frame_inherit\": true,\n  \"frame_unit\": \"m\"";
  array_field(out, "vertices_coords", vertices.size(), [&](std::size_t i) {
    return json::array({vertices[i].x(), vertices[i].y(), vertices[i].z()});
  });
  out << "\n  }";
}

}  // namespace

std::string fold_text(const CreasePattern& p) {
  const bool v12 =
      has_assignment(p, EdgeAssignment::Cut) || has_assignment(p, EdgeAssignment::Join);
  std::ostringstream out;
  out << "{\n  \"file_spec\": " << (v12 ? "1.2" : "1.1");
  out << ",\n  \"file_creator\": "
      << json(p.meta.file_creator.empty() ? "finseg" : p.meta.file_creator).dump();
  out << ",\n  \"file_classes\": [\"singleModel\"]";
  if (!p.meta.frame_title.empty())
    out << ",\n  \"frame_title\": " << json(p.meta.frame_title).dump();
  out << ",\n  \"frame_classes\": [\"creasePattern\"]";
  out << ",\n  \"frame_attributes\": [\"2D\"]";
  out << ",\n  \"frame_unit\": \"m\"";
  array_field(out, "vertices_coords", p.vertices_flat_m.size(), [&](std::size_t i) {
    return json::array({p.vertices_flat_m[i].x(), p.vertices_flat_m[i].y()});
  });
  array_field(out, "faces_vertices", p.faces.size(),
              [&](std::size_t i) { return json(p.faces[i]); });
  array_field(out, "edges_vertices", p.edges.size(), [&](std::size_t i) {
    return json::array({p.edges[i].vertices[0], p.edges[i].vertices[1]});
  });
  array_field(out, "edges_assignment", p.edges.size(), [&](std::size_t i) {
    return json(std::string(1, static_cast<char>(p.edges[i].assignment)));
  });
  if (p.has_fold_angles) {
    array_field(out, "edges_foldAngle", p.edges.size(),
                [&](std::size_t i) { return json(p.edges[i].fold_angle / kDegToRad); });
  }
  if (!p.seams.empty()) {
    array_field(out, kSeamsField, p.seams.size(), [&](std::size_t i) {
      return json::array({p.seams[i][0], p.seams[i][1]});
    });
  }
  if (!p.vertices_folded_m.empty()) {
    out << ",\n  \"file_frames\": [";
    folded_frame(out, "", p.vertices_folded_m);
    for (const PatternShape& shape : p.shapes) {
      out << ", ";
      folded_frame(out, shape.title, shape.vertices_m);
    }
    out << "]";
  }
  out << "\n}\n";
  return out.str();
}

void write_fold(const std::string& path, const CreasePattern& p) {
  write_file_atomically(path, fold_text(p));
}

}  // namespace finseg

// parse_fold / read_fold (fold_format.hpp): JSON types, numbers, dimensions and units are
// checked here; topology and geometry in validate_pattern.
#include <fmt/format.h>

#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>

#include "core/error.hpp"
#include "patterns/fold_format.hpp"
#include "patterns/pattern_checks.hpp"
#include "writers/atomic_write.hpp"

namespace finseg {
namespace {

using nlohmann::json;

struct Ctx {
  const std::string& src;
  std::string prefix;  // "" for the key frame, "file_frames[k]." for another frame
  std::string field(const char* name) const { return prefix + name; }
  std::string field(const char* name, std::size_t i) const {
    return fmt::format("{}{}[{}]", prefix, name, i);
  }
};

const json* find(const json& obj, const char* key) {
  const auto it = obj.find(key);
  return it == obj.end() ? nullptr : &*it;
}

const json& require_array(const json* node, const Ctx& c, const char* key) {
  if (!node) throw InputError(c.src, c.field(key), "required");
  if (!node->is_array()) throw InputError(c.src, c.field(key), "must be an array");
  return *node;
}

std::string optional_string(const json& obj, const Ctx& c, const char* key) {
  const json* n = find(obj, key);
  if (!n) return {};
  if (!n->is_string()) throw InputError(c.src, c.field(key), "must be a string");
  return n->get<std::string>();
}

std::vector<std::string> string_list(const json& obj, const Ctx& c, const char* key) {
  std::vector<std::string> out;
  const json* n = find(obj, key);
  if (!n) return out;
  if (!n->is_array()) throw InputError(c.src, c.field(key), "must be an array of strings");
  for (std::size_t i = 0; i < n->size(); ++i) {
    if (!(*n)[i].is_string()) throw InputError(c.src, c.field(key, i), "must be a string");
    out.push_back((*n)[i].get<std::string>());
  }
  return out;
}

bool has(const std::vector<std::string>& list, const char* item) {
  for (const std::string& s : list) {
    if (s == item) return true;
  }
  return false;
}

double finite_number(const json& n, const Ctx& c, const std::string& field) {
  if (!n.is_number()) throw InputError(c.src, field, "must be a number");
  const double v = n.get<double>();
  if (!std::isfinite(v)) throw InputError(c.src, field, "must be finite");
  return v;
}

int index_value(const json& n, const Ctx& c, const std::string& field,
                const char* what = "a vertex") {
  if (!n.is_number_integer() || n.get<long long>() < 0 ||
      n.get<long long>() > std::numeric_limits<int>::max()) {
    throw InputError(c.src, field,
                     fmt::format("{} is not {} index (integer >= 0)", n.dump(), what));
  }
  return static_cast<int>(n.get<long long>());
}

// Coordinates of each vertex, 2 or 3 of them, all vertices alike; z = 0 when 2-D.
std::vector<Vec3> read_coords(const json& frame, const Ctx& c, int& dim) {
  const json& arr = require_array(find(frame, "vertices_coords"), c, "vertices_coords");
  std::vector<Vec3> out;
  out.reserve(arr.size());
  for (std::size_t i = 0; i < arr.size(); ++i) {
    const json& v = arr[i];
    const std::string field = c.field("vertices_coords", i);
    if (!v.is_array() || v.size() < 2 || v.size() > 3) {
      throw InputError(c.src, field, "must be an array of 2 or 3 numbers");
    }
    if (i == 0) dim = static_cast<int>(v.size());
    if (static_cast<int>(v.size()) != dim) {
      throw InputError(
          c.src, field,
          fmt::format("{} coordinates, vertex 0 has {}: mixed 2-D/3-D", v.size(), dim));
    }
    Vec3 p = Vec3::Zero();
    for (std::size_t k = 0; k < v.size(); ++k) p[k] = finite_number(v[k], c, field);
    out.push_back(p);
  }
  return out;
}

double frame_scale(const json& frame, const Ctx& c, std::optional<double> given, double inherited) {
  const json* n = find(frame, "frame_unit");
  if (!n) return c.prefix.empty() ? (given ? *given : -1) : inherited;
  if (!n->is_string()) throw InputError(c.src, c.field("frame_unit"), "must be a string");
  const std::string name = n->get<std::string>();
  if (name == "unit") return given ? *given : -1;
  const auto m = metres_per_fold_unit(name);
  if (!m) {
    throw InputError(c.src, c.field("frame_unit"),
                     fmt::format("'{}' unknown; allowed: unit, in, pt, m, cm, mm, um, nm", name));
  }
  if (given && std::abs(*given - *m) > 1e-12 * *m) {
    throw InputError(c.src, c.field("frame_unit"),
                     fmt::format("'{}' but the unit given with the file is {} m", name, *given));
  }
  return *m;
}

std::vector<std::vector<int>> read_faces(const json& frame, const Ctx& c) {
  const json& arr = require_array(find(frame, "faces_vertices"), c, "faces_vertices");
  std::vector<std::vector<int>> faces(arr.size());
  for (std::size_t f = 0; f < arr.size(); ++f) {
    const std::string field = c.field("faces_vertices", f);
    if (!arr[f].is_array()) throw InputError(c.src, field, "must be an array of vertex indices");
    for (const json& v : arr[f]) faces[f].push_back(index_value(v, c, field));
  }
  return faces;
}

std::vector<PatternEdge> read_edges(const json& frame, const Ctx& c) {
  const json& arr = require_array(find(frame, "edges_vertices"), c, "edges_vertices");
  std::vector<PatternEdge> edges(arr.size());
  for (std::size_t e = 0; e < arr.size(); ++e) {
    const std::string field = c.field("edges_vertices", e);
    if (!arr[e].is_array() || arr[e].size() != 2) {
      throw InputError(c.src, field, "must be a pair [u, v] of vertex indices");
    }
    edges[e].vertices = {index_value(arr[e][0], c, field), index_value(arr[e][1], c, field)};
  }
  return edges;
}

const json& parallel_array(const json& frame, const Ctx& c, const char* key, std::size_t n) {
  const json& arr = require_array(find(frame, key), c, key);
  if (arr.size() != n) {
    throw InputError(c.src, c.field(key),
                     fmt::format("{} entries; edges_vertices has {}", arr.size(), n));
  }
  return arr;
}

// Assignments and fold angles; missing assignments are derived after adjacency (docs/fold.md).
bool read_edge_data(const json& frame, const Ctx& c, std::vector<PatternEdge>& edges,
                    bool& has_angles) {
  const bool has_assign = find(frame, "edges_assignment") != nullptr;
  has_angles = find(frame, "edges_foldAngle") != nullptr;
  if (has_assign) {
    const json& arr = parallel_array(frame, c, "edges_assignment", edges.size());
    for (std::size_t e = 0; e < arr.size(); ++e) {
      const std::string s = arr[e].is_string() ? arr[e].get<std::string>() : arr[e].dump();
      if (s.size() != 1 || !assignment_from_letter(s[0], edges[e].assignment)) {
        throw InputError(c.src, c.field("edges_assignment", e),
                         fmt::format("'{}'; allowed: M, V, F, B, U, C, J", s));
      }
    }
  }
  if (has_angles) {
    const json& arr = parallel_array(frame, c, "edges_foldAngle", edges.size());
    for (std::size_t e = 0; e < arr.size(); ++e) {
      edges[e].fold_angle = finite_number(arr[e], c, c.field("edges_foldAngle", e)) * kDegToRad;
    }
  }
  return has_assign;
}

// finseg's own field (docs/fold.md): pairs [edge_a, edge_b] of boundary edges joined as one
// line; checked against the edges in validate_pattern.
std::vector<std::array<int, 2>> read_seams(const json& root, const Ctx& c) {
  std::vector<std::array<int, 2>> seams;
  const json* n = find(root, kSeamsField);
  if (!n) return seams;
  if (!n->is_array()) throw InputError(c.src, kSeamsField, "must be an array of [edge, edge]");
  for (std::size_t i = 0; i < n->size(); ++i) {
    const json& pair = (*n)[i];
    const std::string field = c.field(kSeamsField, i);
    if (!pair.is_array() || pair.size() != 2) {
      throw InputError(c.src, field, "must be a pair [edge_a, edge_b] of edge indices");
    }
    seams.push_back(
        {index_value(pair[0], c, field, "an edge"), index_value(pair[1], c, field, "an edge")});
  }
  return seams;
}

void derive_assignments(CreasePattern& p, const std::string& src) {
  derive_edge_faces(p, src);
  for (PatternEdge& e : p.edges) {
    if (e.face_count() < 2) {
      e.assignment = EdgeAssignment::Boundary;
    } else if (e.fold_angle != 0) {
      e.assignment = e.fold_angle < 0 ? EdgeAssignment::Mountain : EdgeAssignment::Valley;
    } else {
      e.assignment = EdgeAssignment::Flat;
    }
  }
}

void read_meta(const json& root, const Ctx& c, PatternMeta& meta) {
  if (const json* n = find(root, "file_spec")) {
    meta.file_spec = finite_number(*n, c, "file_spec");
    if (std::floor(meta.file_spec) != 1) {
      throw InputError(c.src, "file_spec",
                       fmt::format("{}; finseg reads FOLD version 1.x", meta.file_spec));
    }
  }
  meta.file_creator = optional_string(root, c, "file_creator");
  meta.frame_title = optional_string(root, c, "frame_title");
  string_list(root, c, "file_classes");
  string_list(root, c, "frame_attributes");
  if (has(string_list(root, c, "frame_classes"), "foldedForm")) {
    throw InputError(c.src, "frame_classes",
                     "the key frame is a folded form; finseg needs the flat crease pattern "
                     "there (a folded form goes in file_frames, docs/fold.md)");
  }
}

void require_flat(const std::vector<Vec3>& xyz, const Ctx& c) {
  Eigen::AlignedBox3d box;
  for (const Vec3& p : xyz) box.extend(p);
  const double size = box.diagonal().norm();
  for (std::size_t i = 0; i < xyz.size(); ++i) {
    if (std::abs(xyz[i].z()) > 1e-9 * size) {
      throw InputError(c.src, c.field("vertices_coords", i),
                       "z != 0: the key frame must be the flat crease pattern (a folded form "
                       "goes in file_frames, docs/fold.md)");
    }
  }
}

// The file_frames entries classed "foldedForm", on the key frame's mesh: the first is the
// folded form (vertices_folded_m), each later one a named shape (PatternShape).
void read_folded_frames(const json& root, const Ctx& key, double key_scale,
                        std::optional<double> given, CreasePattern& p) {
  const json* frames = find(root, "file_frames");
  if (!frames) return;
  if (!frames->is_array()) throw InputError(key.src, "file_frames", "must be an array");
  bool first = true;
  for (std::size_t k = 0; k < frames->size(); ++k) {
    const json& fr = (*frames)[k];
    const Ctx c{key.src, fmt::format("file_frames[{}].", k)};
    if (!fr.is_object())
      throw InputError(c.src, fmt::format("file_frames[{}]", k), "must be an object");
    if (!has(string_list(fr, c, "frame_classes"), "foldedForm")) continue;
    for (const char* topo : {"faces_vertices", "edges_vertices"}) {
      const json* mine = find(fr, topo);
      const json* theirs = find(root, topo);
      if (mine && (!theirs || *mine != *theirs)) {
        throw InputError(c.src, c.field(topo),
                         "differs from the key frame's; the folded form must keep its mesh");
      }
    }
    int dim = 0;
    const double scale = frame_scale(fr, c, given, key_scale);
    if (scale < 0) throw InputError(c.src, c.field("frame_unit"), "\"unit\" (no physical length)");
    std::vector<Vec3> xyz = read_coords(fr, c, dim);
    for (Vec3& v : xyz) v *= scale;
    if (first) {
      p.vertices_folded_m = std::move(xyz);
      first = false;
      continue;
    }
    std::string title = optional_string(fr, c, "frame_title");
    if (title.empty()) title = fmt::format("file_frames[{}]", k);
    for (const PatternShape& earlier : p.shapes) {
      if (earlier.title == title) {
        throw InputError(c.src, c.field("frame_title"),
                         fmt::format("'{}' is the title of an earlier folded frame; the "
                                     "shapes a probe names must differ",
                                     title));
      }
    }
    p.shapes.push_back({title, std::move(xyz)});
  }
}

}  // namespace

std::optional<double> metres_per_fold_unit(const std::string& name) {
  if (name == "m") return 1.0;
  if (name == "cm") return 1e-2;
  if (name == "mm") return 1e-3;
  if (name == "um") return 1e-6;
  if (name == "nm") return 1e-9;
  if (name == "in") return 0.0254;
  if (name == "pt") return 0.0254 / 72;
  return std::nullopt;
}

CreasePattern parse_fold(const std::string& text, const std::string& src,
                         std::optional<double> metres_per_unit) {
  if (metres_per_unit && !(*metres_per_unit > 0 && std::isfinite(*metres_per_unit))) {
    throw InputError(src, "unit",
                     fmt::format("{} m per unit; must be finite and > 0", *metres_per_unit));
  }
  json root;
  try {
    root = json::parse(text);
  } catch (const json::parse_error& e) {
    throw InputError(src, "json", fmt::format("not valid JSON (byte {})", e.byte));
  } catch (const json::exception& e) {  // e.g. a number beyond the range of a double
    const std::string what = e.what();
    throw InputError(src, "json", what.substr(what.find("] ") + 2));
  }
  const Ctx c{src, ""};
  if (!root.is_object()) throw InputError(src, "json", "the top level must be an object");
  CreasePattern p;
  read_meta(root, c, p.meta);
  const double scale = frame_scale(root, c, metres_per_unit, -1);
  if (scale < 0) {
    throw InputError(src, "frame_unit",
                     "absent or \"unit\" (no physical length); give the length of one unit "
                     "(scene, or --unit), or write the file in m, cm, mm, um, nm, in or pt");
  }
  int dim = 0;
  const std::vector<Vec3> xyz = read_coords(root, c, dim);
  if (dim == 3) require_flat(xyz, c);
  for (const Vec3& v : xyz) p.vertices_flat_m.emplace_back(v.x() * scale, v.y() * scale);
  p.faces = read_faces(root, c);
  if (find(root, "edges_vertices")) {
    p.edges = read_edges(root, c);
    if (!read_edge_data(root, c, p.edges, p.has_fold_angles)) derive_assignments(p, src);
  } else {
    for (const char* key : {"edges_assignment", "edges_foldAngle"}) {
      if (find(root, key)) throw InputError(src, key, "given without edges_vertices");
    }
    p.edges = edges_from_faces(p.faces);
  }
  p.seams = read_seams(root, c);
  read_folded_frames(root, c, scale, metres_per_unit, p);
  validate_pattern(p, src);
  return p;
}

CreasePattern read_fold(const std::string& path, std::optional<double> metres_per_unit) {
  std::string text;
  try {
    text = read_whole_file(path);
  } catch (const std::runtime_error& e) {
    throw InputError(path, "file", e.what());
  }
  return parse_fold(text, path, metres_per_unit);
}

}  // namespace finseg

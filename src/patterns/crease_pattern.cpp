#include "patterns/crease_pattern.hpp"

#include <fmt/format.h>

#include <cstdint>
#include <unordered_map>

#include "core/error.hpp"

namespace finseg {
namespace {

std::uint64_t edge_key(int a, int b) {
  if (a > b) std::swap(a, b);
  return (static_cast<std::uint64_t>(a) << 32) | static_cast<std::uint32_t>(b);
}

}  // namespace

bool is_crease(EdgeAssignment a) {
  return a == EdgeAssignment::Mountain || a == EdgeAssignment::Valley ||
         a == EdgeAssignment::Flat || a == EdgeAssignment::Unassigned;
}

bool assignment_from_letter(char c, EdgeAssignment& out) {
  for (char l : {'M', 'V', 'F', 'B', 'U', 'C', 'J'}) {
    if (c == l) {
      out = static_cast<EdgeAssignment>(c);
      return true;
    }
  }
  return false;
}

void derive_edge_faces(CreasePattern& p, const std::string& source) {
  std::unordered_map<std::uint64_t, int> index;
  index.reserve(p.edges.size() * 2);
  for (std::size_t e = 0; e < p.edges.size(); ++e) {
    PatternEdge& edge = p.edges[e];
    edge.faces = {-1, -1};
    const auto [it, fresh] = index.emplace(edge_key(edge.vertices[0], edge.vertices[1]), e);
    if (!fresh) {
      throw InputError(source, fmt::format("edges_vertices[{}]", e),
                       fmt::format("joins vertices {} and {}, as edge {} does already",
                                   edge.vertices[0], edge.vertices[1], it->second));
    }
  }
  for (std::size_t f = 0; f < p.faces.size(); ++f) {
    const std::vector<int>& loop = p.faces[f];
    for (std::size_t i = 0; i < loop.size(); ++i) {
      const int a = loop[i], b = loop[(i + 1) % loop.size()];
      const auto it = index.find(edge_key(a, b));
      const std::string field = fmt::format("faces_vertices[{}]", f);
      if (it == index.end()) {
        throw InputError(source, field,
                         fmt::format("side {} -> {} is not an edge in edges_vertices", a, b));
      }
      PatternEdge& edge = p.edges[it->second];
      const int side = edge.vertices[0] == a ? 0 : 1;  // left of u -> v runs u -> v
      if (edge.faces[side] >= 0) {
        const bool third = edge.faces[1 - side] >= 0;
        throw InputError(
            source, fmt::format("edges_vertices[{}]", it->second),
            third ? fmt::format("shared by more than two faces ({}, {}, {}): non-manifold",
                                edge.faces[0], edge.faces[1], f)
                  : fmt::format("faces {} and {} both run it {} -> {}: one of them is "
                                "clockwise (faces must be counter-clockwise)",
                                edge.faces[side], f, a, b));
      }
      edge.faces[side] = static_cast<int>(f);
    }
  }
}

std::vector<PatternEdge> edges_from_faces(const std::vector<std::vector<int>>& faces) {
  std::unordered_map<std::uint64_t, int> index;
  std::vector<PatternEdge> edges;
  for (const std::vector<int>& loop : faces) {
    for (std::size_t i = 0; i < loop.size(); ++i) {
      const int a = loop[i], b = loop[(i + 1) % loop.size()];
      const auto [it, fresh] = index.emplace(edge_key(a, b), static_cast<int>(edges.size()));
      if (fresh) {
        PatternEdge e;
        e.vertices = {a, b};
        e.assignment = EdgeAssignment::Boundary;
        edges.push_back(e);
      } else {
        edges[it->second].assignment = EdgeAssignment::Flat;
      }
    }
  }
  return edges;
}

}  // namespace finseg

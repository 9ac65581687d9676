#include "patterns/grid_pattern.hpp"

#include <fmt/format.h>

#include "core/error.hpp"

namespace finseg {

CreasePattern grid_crease_pattern(int nx, int ny, double dx, double dy) {
  if (nx < 1 || ny < 1) throw InputError("<api>", "grid", fmt::format("{} x {} cells", nx, ny));
  CreasePattern p;
  p.meta.file_creator = "finseg";
  p.meta.frame_title = fmt::format("grid {} x {}", nx, ny);
  auto id = [&](int i, int j) { return i * (nx + 1) + j; };
  for (int i = 0; i <= ny; ++i) {
    for (int j = 0; j <= nx; ++j) p.vertices_flat_m.emplace_back(j * dx, i * dy);
  }
  for (int i = 0; i < ny; ++i) {
    for (int j = 0; j < nx; ++j) {
      p.faces.push_back({id(i, j), id(i, j + 1), id(i + 1, j + 1), id(i + 1, j)});
    }
  }
  auto add = [&](int a, int b, bool outline) {
    PatternEdge e;
    e.vertices = {a, b};
    e.assignment = outline ? EdgeAssignment::Boundary : EdgeAssignment::Join;
    p.edges.push_back(e);
  };
  for (int k = 0; k <= std::max(nx, ny); ++k) {
    for (int j = 0; k <= ny && j < nx; ++j) add(id(k, j), id(k, j + 1), k == 0 || k == ny);
    for (int i = 0; k <= nx && i < ny; ++i) add(id(i, k), id(i + 1, k), k == 0 || k == nx);
  }
  derive_edge_faces(p, "<grid>");
  return p;
}

}  // namespace finseg

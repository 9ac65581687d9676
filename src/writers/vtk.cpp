// VTK XML output (ASCII): one .vtu per frame with a hexahedron per segment box, a .pvd
// collection with the frame times, and the same pair for contact points when there are any.
#include "writers/vtk.hpp"

#include <filesystem>
#include <string>

#include <fmt/format.h>

#include "writers/atomic_write.hpp"
#include "writers/frame_check.hpp"

namespace finseg {
namespace {

constexpr int kVtkVertex = 1;
constexpr int kVtkHexahedron = 12;

const char* kUnitsComment =
    "<!-- finseg: lengths in m (SI); timestep = Frame::t, time in s, or the drive "
    "displacement in m for quasi-static runs -->\n";

std::string vtu_header(std::size_t points, std::size_t cells) {
  return fmt::format(
      "<?xml version=\"1.0\"?>\n{}"
      "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" "
      "header_type=\"UInt64\">\n"
      "  <UnstructuredGrid>\n"
      "    <Piece NumberOfPoints=\"{}\" NumberOfCells=\"{}\">\n",
      kUnitsComment, points, cells);
}

const char* kVtuFooter =
    "    </Piece>\n"
    "  </UnstructuredGrid>\n"
    "</VTKFile>\n";

void append_points(std::string& out, const std::vector<Vec3>& points) {
  out += "      <Points>\n";
  out +=
      "        <DataArray type=\"Float64\" Name=\"position_m\" NumberOfComponents=\"3\" "
      "format=\"ascii\">\n";
  for (const Vec3& p : points) {
    out += fmt::format("          {:.10g} {:.10g} {:.10g}\n", p.x(), p.y(), p.z());
  }
  out += "        </DataArray>\n      </Points>\n";
}

void append_cells(std::string& out, std::size_t cells, int nodes_per_cell, int type) {
  out += "      <Cells>\n";
  out += "        <DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n";
  for (std::size_t c = 0; c < cells; ++c) {
    out += "          ";
    for (int k = 0; k < nodes_per_cell; ++k) {
      out += fmt::format("{}{}", k ? " " : "", c * nodes_per_cell + k);
    }
    out += "\n";
  }
  out += "        </DataArray>\n";
  out += "        <DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n";
  for (std::size_t c = 0; c < cells; ++c) {
    out += fmt::format("          {}\n", (c + 1) * nodes_per_cell);
  }
  out += "        </DataArray>\n";
  out += "        <DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n";
  for (std::size_t c = 0; c < cells; ++c) out += fmt::format("          {}\n", type);
  out += "        </DataArray>\n      </Cells>\n";
}

template <class Get>
void append_int_array(std::string& out, const char* name, std::size_t n, Get get) {
  out += fmt::format("        <DataArray type=\"Int32\" Name=\"{}\" format=\"ascii\">\n", name);
  for (std::size_t i = 0; i < n; ++i) out += fmt::format("          {}\n", get(i));
  out += "        </DataArray>\n";
}

std::string bodies_vtu(const Model& model, const Frame& frame) {
  const std::size_t n = model.bodies.size();
  std::vector<Vec3> points;
  points.reserve(8 * n);
  for (std::size_t b = 0; b < n; ++b) {
    for (const Vec3& c : box_corners_W(model.bodies[b].size, frame.p_W[b], frame.R_WB[b])) {
      points.push_back(c);
    }
  }
  std::string out = vtu_header(points.size(), n);
  append_points(out, points);
  append_cells(out, n, 8, kVtkHexahedron);
  out += "      <CellData Scalars=\"panel\">\n";
  append_int_array(out, "body", n, [](std::size_t i) { return static_cast<int>(i); });
  // Panels from 1, as in scene files and the HTML legend.
  append_int_array(out, "panel", n, [&](std::size_t i) { return model.bodies[i].panel + 1; });
  append_int_array(out, "fixed", n, [&](std::size_t i) { return model.bodies[i].fixed ? 1 : 0; });
  out += "      </CellData>\n";
  out += kVtuFooter;
  return out;
}

std::string contacts_vtu(const Frame& frame) {
  const std::vector<Vec3>& pts = frame.contact_points_W;
  std::string out = vtu_header(pts.size(), pts.size());
  append_points(out, pts);
  append_cells(out, pts.size(), 1, kVtkVertex);
  out += kVtuFooter;
  return out;
}

std::string pvd(const std::vector<Frame>& frames, const std::vector<std::string>& files) {
  std::string out = "<?xml version=\"1.0\"?>\n";
  out += kUnitsComment;
  out += "<VTKFile type=\"Collection\" version=\"1.0\" byte_order=\"LittleEndian\">\n";
  out += "  <Collection>\n";
  for (std::size_t f = 0; f < frames.size(); ++f) {
    out += fmt::format("    <DataSet timestep=\"{:.17g}\" part=\"0\" file=\"{}\"/>\n", frames[f].t,
                       files[f]);
  }
  out += "  </Collection>\n</VTKFile>\n";
  return out;
}

}  // namespace

void write_vtk_series(const std::string& dir, const std::string& stem, const Model& model,
                      const std::vector<Frame>& frames) {
  check_frames(model, frames);
  namespace fs = std::filesystem;
  fs::create_directories(dir);
  const fs::path base(dir);

  bool any_contacts = false;
  for (const Frame& f : frames) any_contacts = any_contacts || !f.contact_points_W.empty();

  std::vector<std::string> body_files, contact_files;
  for (std::size_t f = 0; f < frames.size(); ++f) {
    const std::string name = fmt::format("{}_{:05d}.vtu", stem, f);
    write_file_atomically((base / name).string(), bodies_vtu(model, frames[f]));
    body_files.push_back(name);
    if (any_contacts) {
      const std::string cname = fmt::format("{}_contacts_{:05d}.vtu", stem, f);
      write_file_atomically((base / cname).string(), contacts_vtu(frames[f]));
      contact_files.push_back(cname);
    }
  }
  // The collections last: they only ever list files that are complete on disk.
  if (any_contacts) {
    write_file_atomically((base / (stem + "_contacts.pvd")).string(), pvd(frames, contact_files));
  }
  write_file_atomically((base / (stem + ".pvd")).string(), pvd(frames, body_files));
}

}  // namespace finseg

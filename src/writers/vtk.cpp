// Placeholder until the VTK writer lands.
#include "writers/vtk.hpp"

#include <stdexcept>

namespace finseg {

void write_vtk_series(const std::string&, const std::string&, const Model&,
                      const std::vector<Frame>&) {
  throw std::runtime_error("VTK output is not implemented yet");
}

}  // namespace finseg

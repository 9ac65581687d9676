// Placeholder until the gnuplot writer lands.
#include "writers/plot.hpp"

#include <stdexcept>

namespace finseg {

void write_plot(const std::string&, const PlotSpec&) {
  throw std::runtime_error("plots are not implemented yet");
}

}  // namespace finseg

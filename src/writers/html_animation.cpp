// Placeholder until the HTML animation writer lands.
#include "writers/html_animation.hpp"

#include <stdexcept>

namespace finseg {

void write_html_animation(const std::string&, const std::string&, const Model&,
                          const std::vector<Frame>&, const Curve&) {
  throw std::runtime_error("HTML animation is not implemented yet");
}

}  // namespace finseg

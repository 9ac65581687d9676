// Contact settings of a model (filled in by the contact module).
#pragma once

namespace finseg {

/// Contact between segments: off unless enabled.
struct ContactDef {
  bool enabled = false;
};

}  // namespace finseg

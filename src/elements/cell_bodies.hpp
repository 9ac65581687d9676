// The bodies a cell's forces reach (its own and its sides' neighbours), numbered locally in
// first-seen order, for the cell's dense Jacobian before it is scattered into blocks.
#pragma once

#include <algorithm>
#include <vector>

namespace finseg {

/// Local numbering of a cell's bodies; local(b) adds b the first time it is seen.
class CellBodies {
 public:
  /// Local index of `body`, added if new.
  int local(int body) {
    const auto it = std::find(bodies_.begin(), bodies_.end(), body);
    if (it != bodies_.end()) return static_cast<int>(it - bodies_.begin());
    bodies_.push_back(body);
    return static_cast<int>(bodies_.size()) - 1;
  }
  int size() const { return static_cast<int>(bodies_.size()); }
  /// The model's index of local body i.
  int body(int i) const { return bodies_[i]; }
  void clear() { bodies_.clear(); }

 private:
  std::vector<int> bodies_;
};

}  // namespace finseg

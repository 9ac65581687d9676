// Base of the crease laws made from another law (scaled, shifted, relaxing): what they do
// not change (opening rule, angle convention, data files) is the wrapped law's.
#pragma once

#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "elements/crease_law.hpp"

namespace finseg {

class WrappedCreaseLaw : public CreaseLaw {
 public:
  explicit WrappedCreaseLaw(std::shared_ptr<const CreaseLaw> law) : law_(std::move(law)) {}
  OpeningRule opening_rule() const override { return law_->opening_rule(); }
  bool direction_relative() const override { return law_->direction_relative(); }
  std::vector<std::string> data_files() const override { return law_->data_files(); }

 protected:
  std::shared_ptr<const CreaseLaw> law_;  ///< the law this one is made from
};

}  // namespace finseg

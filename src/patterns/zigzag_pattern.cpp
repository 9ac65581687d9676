#include "patterns/zigzag_pattern.hpp"

#include <fmt/format.h>

#include "generators/sheet_pattern_model.hpp"

namespace finseg {

CreasePattern zigzag_crease_pattern(const ZigzagSpec& spec, bool cells) {
  CreasePattern p = sheet_crease_pattern(zigzag_sheet(spec), cells).pattern;  // validates
  p.meta.file_creator = "finseg";
  p.meta.frame_title = fmt::format("zigzag strip, {} panels", spec.panels);
  return p;
}

Model build_zigzag_pattern_model(const ZigzagSpec& spec, bool crease_bending_in_series) {
  Model m = build_sheet_pattern_model(zigzag_sheet(spec), crease_bending_in_series);
  add_zigzag_rig(m, spec);
  return m;
}

}  // namespace finseg

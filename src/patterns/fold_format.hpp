// FOLD files (the origami community's JSON format, spec 1.1/1.2) <-> CreasePattern.
// docs/fold.md says which fields are read, the units, the sign convention and every rule
// by which a file is refused.
#pragma once

#include <optional>
#include <string>

#include "patterns/crease_pattern.hpp"

namespace finseg {

/// finseg's custom FOLD field holding CreasePattern::seams.
inline constexpr const char* kSeamsField = "finseg:seams";

/// Metres per FOLD frame_unit `name` ("m", "cm", "mm", "um", "nm", "in", "pt"); nullopt for
/// "unit" (no physical meaning) and for names FOLD does not define.
std::optional<double> metres_per_fold_unit(const std::string& name);

/// Parses and validates FOLD text (validate_pattern included); `source` names it in errors.
/// `metres_per_unit` gives the scale of a unitless file (frame_unit "unit" or absent), which
/// is refused without it; for a file with a physical unit it must agree with that unit.
CreasePattern parse_fold(const std::string& text, const std::string& source,
                         std::optional<double> metres_per_unit = {});

/// parse_fold on the contents of `path`; InputError names `path`.
CreasePattern read_fold(const std::string& path, std::optional<double> metres_per_unit = {});

/// FOLD 1.1 text of `p` (1.2 when it has C or J edges): metres, frame_unit "m", the folded
/// coordinates as a "foldedForm" frame in file_frames; one line per vertex, face and edge,
/// numbers in shortest round-trip form, so the same pattern always gives the same bytes.
std::string fold_text(const CreasePattern& p);

/// Writes fold_text(p) to `path` atomically.
void write_fold(const std::string& path, const CreasePattern& p);

}  // namespace finseg

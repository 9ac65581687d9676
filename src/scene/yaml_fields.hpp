// Typed, validated access to one YAML map of a scene file: every value is checked where it
// enters and a bad one throws InputError(file, "dotted.field", "value; allowed range").
#pragma once

#include <cmath>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "core/types.hpp"
#include "scene/sections.hpp"

namespace finseg {

/// Allowed interval of a number and its unit, for checks and messages.
struct Range {
  double min = -INFINITY, max = INFINITY;
  bool min_open = false, max_open = false;
  std::string unit;
  bool contains(double x) const;
  std::string describe() const;  ///< e.g. "> 0 m", "[0, 0.5)"
};
Range positive(const std::string& unit);      ///< (0, inf)
Range non_negative(const std::string& unit);  ///< [0, inf)
Range any_finite(const std::string& unit);    ///< (-inf, inf), finite
Range interval(double a, double b, bool a_open, bool b_open, const std::string& unit = "");

/// Dotted child path: "a" + "b" -> "a.b"; "" + "b" -> "b".
std::string child_field(const std::string& parent, const std::string& key);

/// A YAML map with a fixed set of allowed keys. Unknown keys throw on construction.
class Fields {
 public:
  Fields(const YAML::Node& node, YamlContext ctx, const std::set<std::string>& allowed);

  bool has(const std::string& key) const { return static_cast<bool>(node_[key]); }
  YAML::Node node(const std::string& key) const { return node_[key]; }
  YamlContext context(const std::string& key) const { return {ctx_.file, field(key)}; }
  std::string field(const std::string& key) const { return child_field(ctx_.field, key); }
  const YamlContext& context() const { return ctx_; }

  [[noreturn]] void fail(const std::string& key, const std::string& what) const;

  double number(const std::string& key, const Range& range) const;  ///< required
  double number(const std::string& key, double fallback, const Range& range) const;
  std::optional<double> optional_number(const std::string& key, const Range& range) const;
  int integer(const std::string& key, int fallback, int min, int max) const;
  bool flag(const std::string& key, bool fallback) const;
  std::string word(const std::string& key, const std::string& fallback) const;
  std::string required_word(const std::string& key) const;
  Vec3 vector3(const std::string& key, const Vec3& fallback, const std::string& unit) const;
  std::vector<int> integers(const std::string& key, int min, int max) const;
  std::vector<double> numbers(const std::string& key, const Range& range) const;
  std::vector<std::string> words(const std::string& key) const;

 private:
  YAML::Node node_;
  YamlContext ctx_;
};

/// Reads a scalar number at `node` (field for messages) and checks `range`.
double read_number_at(const YAML::Node& node, const YamlContext& ctx, const Range& range);

/// The elements of a YAML sequence (empty when absent); throws if it is not a list.
std::vector<YAML::Node> sequence(const YAML::Node& node, const YamlContext& ctx,
                                 const std::string& what);

/// Walks every map of the tree under `node` and throws InputError naming the dotted field
/// and both line numbers when a key appears twice (yaml-cpp keeps both; `node[key]` would
/// silently return the first).
void refuse_duplicate_keys(const YAML::Node& node, const YamlContext& ctx);

/// Parses YAML text read from `file` whose top level must be a map (`what` says of what,
/// e.g. "a map of sections"); duplicate keys refused. Throws InputError naming the line.
YAML::Node load_yaml_map(const std::string& text, const std::string& file, const std::string& what);

/// Reads the YAML file `path` (load_yaml_map) as the top-level Fields of a map with the keys
/// `allowed` (sweep and fit files).
Fields read_fields_file(const std::string& path, const std::set<std::string>& allowed);

/// A path named inside `file` (a scene, sweep or fit file): relative ones are taken from the
/// folder of `file`.
std::string path_beside(const std::string& file, const std::string& named);

/// Field name of element i of a list: "loads" -> "loads[2]".
std::string item_field(const std::string& list, std::size_t i);

}  // namespace finseg

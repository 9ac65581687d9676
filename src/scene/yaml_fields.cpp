#include "scene/yaml_fields.hpp"

#include <fmt/format.h>

#include <filesystem>
#include <map>

#include "core/error.hpp"
#include "core/text.hpp"

namespace finseg {

bool Range::contains(double x) const {
  if (!std::isfinite(x)) return false;
  const bool lo = min_open ? x > min : x >= min;
  const bool hi = max_open ? x < max : x <= max;
  return lo && hi;
}

std::string Range::describe() const {
  const std::string u = unit.empty() ? "" : " " + unit;
  const bool has_min = std::isfinite(min), has_max = std::isfinite(max);
  if (has_min && has_max) {
    return fmt::format("{}{:g}, {:g}{}{}", min_open ? "(" : "[", min, max, max_open ? ")" : "]", u);
  }
  if (has_min) return fmt::format("{} {:g}{}", min_open ? ">" : ">=", min, u);
  if (has_max) return fmt::format("{} {:g}{}", max_open ? "<" : "<=", max, u);
  return "any finite number" + (unit.empty() ? std::string() : " (" + unit + ")");
}

Range positive(const std::string& unit) {
  return {0.0, INFINITY, true, false, unit};
}
Range non_negative(const std::string& unit) {
  return {0.0, INFINITY, false, false, unit};
}
Range any_finite(const std::string& unit) {
  return {-INFINITY, INFINITY, false, false, unit};
}
Range interval(double a, double b, bool a_open, bool b_open, const std::string& unit) {
  return {a, b, a_open, b_open, unit};
}

std::string child_field(const std::string& parent, const std::string& key) {
  return parent.empty() ? key : parent + "." + key;
}

std::string item_field(const std::string& list, std::size_t i) {
  return fmt::format("{}[{}]", list, i);
}

double read_number_at(const YAML::Node& node, const YamlContext& ctx, const Range& range) {
  if (!node.IsScalar()) {
    throw InputError(ctx.file, ctx.field, "must be a number; allowed range " + range.describe());
  }
  double x = 0;
  try {
    x = node.as<double>();
  } catch (const YAML::Exception&) {
    throw InputError(ctx.file, ctx.field,
                     fmt::format("{} is not a number; allowed range {}", quoted(node.Scalar()),
                                 range.describe()));
  }
  refuse_subnormal(x, ctx.file, ctx.field);
  if (!range.contains(x)) {
    throw InputError(ctx.file, ctx.field,
                     fmt::format("{}{}; allowed range {}", x,
                                 range.unit.empty() ? "" : " " + range.unit, range.describe()));
  }
  return x;
}

namespace {

// Nodes visited by the duplicate-key walk; aliases can make a small file a huge tree.
constexpr long kMaxYamlNodes = 10'000'000;

void walk_keys(const YAML::Node& node, const YamlContext& ctx, long& visited) {
  if (++visited > kMaxYamlNodes) {
    throw InputError(ctx.file, ctx.field.empty() ? "<top level>" : ctx.field,
                     fmt::format("more than {} YAML nodes (aliases?)", kMaxYamlNodes));
  }
  if (node.IsSequence()) {
    for (std::size_t i = 0; i < node.size(); ++i) {
      walk_keys(node[i], {ctx.file, item_field(ctx.field, i)}, visited);
    }
    return;
  }
  if (!node.IsMap()) return;
  std::map<std::string, int> line_of;
  for (const auto& kv : node) {
    if (!kv.first.IsScalar()) continue;  // refused with its line by the section reader
    const std::string key = kv.first.Scalar();
    const int line = kv.first.Mark().line + 1;
    const std::string field = child_field(ctx.field, key);
    if (const auto [it, fresh] = line_of.emplace(key, line); !fresh) {
      throw InputError(
          ctx.file, field,
          fmt::format("given twice (lines {} and {}); each key may appear once", it->second, line));
    }
    walk_keys(kv.second, {ctx.file, field}, visited);
  }
}

}  // namespace

std::string path_beside(const std::string& file, const std::string& named) {
  const std::filesystem::path p(named);
  return p.is_absolute() ? named : (std::filesystem::path(file).parent_path() / p).string();
}

YAML::Node load_yaml_map(const std::string& text, const std::string& file,
                         const std::string& what) {
  YAML::Node root;
  try {
    root = YAML::Load(normalize_text(text));
  } catch (const YAML::Exception& e) {
    throw InputError(file, fmt::format("line {}", e.mark.line + 1),
                     fmt::format("malformed YAML: {}", e.msg));
  }
  if (!root.IsMap()) throw InputError(file, "<top level>", "must be " + what);
  refuse_duplicate_keys(root, {file, ""});
  return root;
}

Fields read_fields_file(const std::string& path, const std::set<std::string>& allowed) {
  return Fields(load_yaml_map(read_text_file(path), path, "a map"), {path, ""}, allowed);
}

void refuse_duplicate_keys(const YAML::Node& node, const YamlContext& ctx) {
  long visited = 0;
  walk_keys(node, ctx, visited);
}

std::vector<YAML::Node> sequence(const YAML::Node& node, const YamlContext& ctx,
                                 const std::string& what) {
  std::vector<YAML::Node> items;
  if (!node || node.IsNull()) return items;
  if (!node.IsSequence()) throw InputError(ctx.file, ctx.field, "must be a list of " + what);
  for (std::size_t i = 0; i < node.size(); ++i) items.push_back(node[i]);
  return items;
}

Fields::Fields(const YAML::Node& node, YamlContext ctx, const std::set<std::string>& allowed)
    // An absent section reads as an empty map (a missing key gives an invalid node, which
    // must not be assigned to).
    : node_(node.IsDefined() && !node.IsNull() ? node : YAML::Node(YAML::NodeType::Map)),
      ctx_(std::move(ctx)) {
  if (!node_.IsMap()) {
    throw InputError(ctx_.file, ctx_.field.empty() ? "<top level>" : ctx_.field,
                     "must be a map of key: value pairs");
  }
  for (const auto& kv : node_) {
    if (!kv.first.IsScalar()) {
      throw InputError(ctx_.file, ctx_.field.empty() ? "<top level>" : ctx_.field,
                       fmt::format("line {}: keys must be plain words", kv.first.Mark().line + 1));
    }
    const std::string key = kv.first.Scalar();
    if (!allowed.count(key)) {
      std::string list;
      for (const std::string& k : allowed) list += (list.empty() ? "" : ", ") + k;
      throw InputError(ctx_.file, field(key), "unknown key; allowed: " + list);
    }
  }
}

void Fields::fail(const std::string& key, const std::string& what) const {
  throw InputError(ctx_.file, field(key), what);
}

double Fields::number(const std::string& key, const Range& range) const {
  if (!has(key)) fail(key, "required; allowed range " + range.describe());
  return read_number_at(node_[key], context(key), range);
}

double Fields::number(const std::string& key, double fallback, const Range& range) const {
  return has(key) ? number(key, range) : fallback;
}

std::optional<double> Fields::optional_number(const std::string& key, const Range& range) const {
  if (!has(key)) return std::nullopt;
  return number(key, range);
}

int Fields::integer(const std::string& key, int fallback, int min, int max) const {
  if (!has(key)) return fallback;
  const YAML::Node v = node_[key];
  const std::string allowed = fmt::format("an integer in [{}, {}]", min, max);
  long long x = 0;
  try {
    if (!v.IsScalar()) throw YAML::Exception(YAML::Mark(), "");
    x = v.as<long long>();
  } catch (const YAML::Exception&) {
    fail(key, fmt::format("{}; must be {}", v.IsScalar() ? quoted(v.Scalar()) : "?", allowed));
  }
  if (x < min || x > max) fail(key, fmt::format("{}; must be {}", x, allowed));
  return static_cast<int>(x);
}

bool Fields::flag(const std::string& key, bool fallback) const {
  if (!has(key)) return fallback;
  try {
    if (!node_[key].IsScalar()) throw YAML::Exception(YAML::Mark(), "");
    return node_[key].as<bool>();
  } catch (const YAML::Exception&) {
    fail(key, "must be true or false");
  }
}

std::string Fields::word(const std::string& key, const std::string& fallback) const {
  if (!has(key)) return fallback;
  if (!node_[key].IsScalar()) fail(key, "must be a single word or string");
  return node_[key].Scalar();
}

std::string Fields::required_word(const std::string& key) const {
  if (!has(key)) fail(key, "required");
  return word(key, "");
}

Vec3 Fields::vector3(const std::string& key, const Vec3& fallback, const std::string& unit) const {
  if (!has(key)) return fallback;
  const YAML::Node v = node_[key];
  if (!v.IsSequence() || v.size() != 3) {
    fail(key, fmt::format("must be a list of three numbers [x, y, z] ({})", unit));
  }
  Vec3 out;
  for (int i = 0; i < 3; ++i) {
    out[i] = read_number_at(v[i], {ctx_.file, item_field(field(key), i)}, any_finite(unit));
  }
  return out;
}

std::vector<int> Fields::integers(const std::string& key, int min, int max) const {
  std::vector<int> out;
  const auto items = sequence(node_[key], context(key), "integers");
  for (std::size_t i = 0; i < items.size(); ++i) {
    const std::string f = item_field(field(key), i);
    double x = read_number_at(items[i], {ctx_.file, f}, interval(min, max, false, false));
    if (x != std::floor(x))
      throw InputError(ctx_.file, f, fmt::format("{}; must be an integer", x));
    out.push_back(static_cast<int>(x));
  }
  return out;
}

std::vector<double> Fields::numbers(const std::string& key, const Range& range) const {
  std::vector<double> out;
  const auto items = sequence(node_[key], context(key), "numbers");
  for (std::size_t i = 0; i < items.size(); ++i) {
    out.push_back(read_number_at(items[i], {ctx_.file, item_field(field(key), i)}, range));
  }
  return out;
}

std::vector<std::string> Fields::words(const std::string& key) const {
  std::vector<std::string> out;
  const auto items = sequence(node_[key], context(key), "names");
  for (std::size_t i = 0; i < items.size(); ++i) {
    if (!items[i].IsScalar()) {
      throw InputError(ctx_.file, item_field(field(key), i), "must be a name");
    }
    out.push_back(items[i].Scalar());
  }
  return out;
}

}  // namespace finseg

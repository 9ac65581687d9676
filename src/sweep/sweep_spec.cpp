#include "sweep/sweep_spec.hpp"

#include <fmt/format.h>

#include "core/error.hpp"
#include "core/text.hpp"
#include "scene/yaml_fields.hpp"

namespace finseg {
namespace {

constexpr std::size_t kMaxCases = 100000;  // a typo in `steps` must not start a million runs

// The values of one parameter: `values: [...]` (any YAML, kept as text) or
// `from`/`to`/`steps` (evenly spaced numbers, both ends included).
std::vector<std::string> parameter_values(const Fields& p) {
  std::vector<std::string> values;
  if (p.has("values")) {
    if (p.has("from") || p.has("to") || p.has("steps")) {
      p.fail("values", "give either values or from/to/steps, not both");
    }
    for (const YAML::Node& v : sequence(p.node("values"), p.context("values"), "values")) {
      YAML::Emitter out;
      out << YAML::Flow << v;
      values.emplace_back(v.IsScalar() ? v.Scalar() : std::string(out.c_str()));
    }
    if (values.empty()) p.fail("values", "at least one value");
    return values;
  }
  const double from = p.number("from", any_finite(""));
  const double to = p.number("to", any_finite(""));
  const int steps = p.integer("steps", 2, 1, static_cast<int>(kMaxCases));
  if (steps == 1 && from != to) p.fail("steps", "1 step needs from == to");
  for (int k = 0; k < steps; ++k) {
    const double x = steps == 1 ? from : from + (to - from) * k / (steps - 1);
    values.push_back(fmt::format("{:.17g}", x));
  }
  return values;
}

}  // namespace

SweepSpec read_sweep(const std::string& path) {
  const Fields f = read_fields_file(path, {"scene", "parameters", "cases", "outputs"});
  SweepSpec s;
  s.file = path;
  s.scene = path_beside(path, f.required_word("scene"));
  const std::string cases = f.word("cases", "factorial");
  if (cases != "factorial" && cases != "listed") f.fail("cases", "factorial or listed");
  s.listed = cases == "listed";
  const auto params = sequence(f.node("parameters"), f.context("parameters"), "parameters");
  if (params.empty()) f.fail("parameters", "at least one parameter");
  for (std::size_t i = 0; i < params.size(); ++i) {
    const Fields p(params[i], {path, item_field("parameters", i)},
                   {"path", "values", "from", "to", "steps"});
    SweepParameter sp{p.required_word("path"), parameter_values(p)};
    parse_override(sp.path + "=0");  // the path's own syntax
    if (s.listed && !s.parameters.empty() && sp.values.size() != s.parameters[0].values.size()) {
      p.fail("values", fmt::format("listed cases need as many values as parameters[0] ({})",
                                   s.parameters[0].values.size()));
    }
    s.parameters.push_back(sp);
  }
  s.outputs = f.has("outputs") ? f.words("outputs") : std::vector<std::string>{"wall_time_s"};
  std::size_t n = s.listed ? s.parameters[0].values.size() : 1;
  if (!s.listed) {
    for (const SweepParameter& p : s.parameters) {
      n *= p.values.size();
      if (n > kMaxCases) f.fail("parameters", fmt::format("more than {} cases", kMaxCases));
    }
  }
  return s;
}

std::vector<std::vector<Override>> sweep_cases(const SweepSpec& spec) {
  std::vector<std::vector<Override>> cases;
  if (spec.listed) {
    for (std::size_t k = 0; k < spec.parameters[0].values.size(); ++k) {
      std::vector<Override> c;
      for (const SweepParameter& p : spec.parameters) c.push_back({p.path, p.values[k]});
      cases.push_back(c);
    }
    return cases;
  }
  cases.push_back({});
  for (const SweepParameter& p : spec.parameters) {
    std::vector<std::vector<Override>> next;
    for (const auto& c : cases) {
      for (const std::string& v : p.values) {
        next.push_back(c);
        next.back().push_back({p.path, v});
      }
    }
    cases = std::move(next);
  }
  return cases;
}

}  // namespace finseg

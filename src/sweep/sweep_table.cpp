#include "sweep/sweep_table.hpp"

#include <fmt/format.h>

namespace finseg {
namespace {

// A CSV cell: numbers as %.10g, text quoted when it holds a comma, quote or line break.
std::string cell(const nlohmann::json& v) {
  if (v.is_null()) return "";
  if (v.is_number()) return fmt::format("{:.10g}", v.get<double>());
  std::string text = v.is_string() ? v.get<std::string>() : v.dump();
  if (text.find_first_of(",\"\n") == std::string::npos) return text;
  std::string q(1, '"');
  for (char c : text) {
    if (c == '"') q.push_back('"');
    q.push_back(c == '\n' ? ' ' : c);
  }
  q.push_back('"');
  return q;
}

}  // namespace

nlohmann::json summary_value(const nlohmann::json& summary, const std::string& key) {
  const nlohmann::json* node = &summary;
  std::size_t start = 0;
  while (true) {
    const std::size_t dot = key.find('.', start);
    const std::string part = key.substr(start, dot - start);
    if (!node->is_object() || !node->contains(part)) return nullptr;
    node = &node->at(part);
    if (dot == std::string::npos) return *node;
    start = dot + 1;
  }
}

std::string sweep_table_csv(const SweepSpec& spec, const std::vector<std::vector<Override>>& cases,
                            const std::vector<SweepCaseResult>& results) {
  std::string csv = "case";
  const auto add = [&csv](const std::string& text) {
    csv.push_back(',');
    csv.append(text);
  };
  for (const SweepParameter& p : spec.parameters) add(cell(p.path));
  add("status");
  for (const std::string& k : spec.outputs) add(cell(k));
  add("message");
  csv.push_back('\n');
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const SweepCaseResult& r = results[i];
    csv.append(std::to_string(i + 1));
    for (const Override& o : cases[i]) add(cell(o.value));
    const bool ran = !r.summary.is_null();
    add(ran ? cell(summary_value(r.summary, "status")) : std::string("failed"));
    for (const std::string& k : spec.outputs) add(cell(summary_value(r.summary, k)));
    add(cell(ran ? summary_value(r.summary, "message") : nlohmann::json(r.failure)));
    csv.push_back('\n');
  }
  return csv;
}

}  // namespace finseg

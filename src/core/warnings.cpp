#include "core/warnings.hpp"

#include <fmt/format.h>

#include <mutex>

namespace finseg {
namespace {

std::mutex& warnings_mutex() {
  static std::mutex m;
  return m;
}

std::vector<std::string>& warnings_list() {
  static std::vector<std::string> list;
  return list;
}

}  // namespace

void warn(const std::string& message) {
  const std::lock_guard<std::mutex> lock(warnings_mutex());
  fmt::print(stderr, "finseg: warning: {}\n", message);
  warnings_list().push_back(message);
}

std::vector<std::string> recorded_warnings() {
  const std::lock_guard<std::mutex> lock(warnings_mutex());
  return warnings_list();
}

void clear_recorded_warnings() {
  const std::lock_guard<std::mutex> lock(warnings_mutex());
  warnings_list().clear();
}

}  // namespace finseg

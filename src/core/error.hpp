// Error types that carry enough context for a one-line diagnosis.
#pragma once

#include <stdexcept>
#include <string>

namespace finseg {

/// Bad input: names the file (or "<api>"), the field and what was allowed.
class InputError : public std::runtime_error {
 public:
  InputError(const std::string& file, const std::string& field, const std::string& what)
      : std::runtime_error(file + ": " + field + ": " + what), file_(file), field_(field) {}
  const std::string& file() const { return file_; }
  const std::string& field() const { return field_; }

 private:
  std::string file_, field_;
};

/// An output that could not be written (disk full, file-size limit, permissions changed
/// during the run); the command exits with status 4.
class OutputError : public std::runtime_error {
 public:
  explicit OutputError(const std::string& what) : std::runtime_error(what) {}
};

/// A simulation that cannot go on (NaN, blow-up, no convergence); says when and where.
class DivergenceError : public std::runtime_error {
 public:
  explicit DivergenceError(const std::string& what) : std::runtime_error(what) {}
};

}  // namespace finseg

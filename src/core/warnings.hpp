// Warnings of the library: printed on stderr as they happen and kept for summary.json.
#pragma once

#include <string>
#include <vector>

namespace finseg {

/// Prints "finseg: warning: <message>" on stderr and keeps the message (thread-safe).
void warn(const std::string& message);

/// Every warning given so far in this process, in order.
std::vector<std::string> recorded_warnings();

/// Forgets the warnings kept so far: a program that runs several scenes (the Python module)
/// starts each run with an empty list, so that its summary.json lists that run's only.
void clear_recorded_warnings();

}  // namespace finseg

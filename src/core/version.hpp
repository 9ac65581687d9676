// Which finseg this is: the project version and the git revision it was built from.
#pragma once

#include <string>

namespace finseg {

/// Project version, e.g. "0.1.0" (CMakeLists.txt, project()).
std::string version();

/// `git rev-parse HEAD` of the checkout at configure time (re-run cmake to refresh it);
/// "unknown" when not built from a git checkout.
std::string git_revision();

}  // namespace finseg

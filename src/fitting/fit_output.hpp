// A fit's results in its output folder (docs/fit.md): fit.json (values, standard errors,
// correlation, statistics), fit.csv (the residual curve) and fit.png (measured band and mean,
// initial and fitted simulation, like `finseg compare`'s plot).
#pragma once

#include <string>

#include "fitting/fit_solve.hpp"

namespace finseg {

/// Writes `dir`/fit.json and fit.csv (creates `dir`); `wall_s` is the fit's wall time, s.
void write_fit(const FitSpec& spec, const FitResult& r, const std::string& dir, double wall_s);

/// Writes `dir`/fit.png (gnuplot). Throws std::runtime_error if gnuplot fails.
void write_fit_plot(const FitSpec& spec, const FitResult& r, const std::string& dir);

}  // namespace finseg

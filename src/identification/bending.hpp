// Bending stiffness from the small-deflection cantilever test (paper section 3.1): tip force
// F against tip displacement x of a clamped strip of free length L.
//
// Continuum (Euler-Bernoulli): x = F L^3 / (3 EI).
// Discrete chain of the sheet generator (N equal cells h = L/N, a joint of stiffness
// k = EI/h at every cell centre s_j = (j - 1/2) h, half cells at clamp and tip): a tip force
// bends joint j by F (L - s_j) / k, so
//   x = F/k sum_j (L - s_j)^2 = F h^2/k sum_{m=0}^{N-1} (m + 1/2)^2 = F h^3 N (4N^2 - 1)/(12 EI)
//     = F L^3 / (3 EI) * (1 - 1/(4 N^2))          (docs/crease-data.md, "Bending").
// Inverting it gives the EI (and k) that make the N-cell model reproduce the measured
// compliance exactly; it is smaller than the continuum EI by the factor 1 - 1/(4N^2).
#pragma once

#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

namespace finseg {

/// Measured cantilever points and the strip geometry the file states (if any).
struct CantileverData {
  std::string source;
  std::vector<double> force;       ///< N
  std::vector<double> deflection;  ///< tip displacement, m
  std::vector<int> line;           ///< file line of each point (empty when not read from a file)
  std::optional<double> length, width, thickness;  ///< m, from "# length_m: ..." lines
};

/// Reads CSV columns force_N and tip_displacement_m (or tip_displacement_mm); comment lines
/// "# length_m: 0.1", "# width_m: ...", "# thickness_m: ..." give the geometry.
CantileverData read_cantilever_data(const std::string& path);
CantileverData parse_cantilever_data(std::istream& in, const std::string& source);

/// Tip compliance of the discrete chain divided by the continuum's L^3/(3EI): 1 - 1/(4N^2).
double chain_compliance_factor(int segments);

struct BendingIdentification {
  double compliance = 0;                 ///< x/F, least squares through the origin, m/N
  double rms_residual = 0;               ///< of x - c F, m
  double max_slope = 0;                  ///< largest x/L: small-deflection theory needs it small
  double length = 0;                     ///< free length L, m
  double EI_continuum = 0;               ///< L^3 / (3 c), N m^2
  int segments = 0;                      ///< N
  double cell_length = 0;                ///< h = L/N, m
  double EI_chain = 0;                   ///< EI that makes the N-cell chain exact, N m^2
  double joint_stiffness = 0;            ///< k = EI_chain / h, N m/rad
  std::optional<double> youngs_modulus;  ///< 12 EI_continuum / (b t^3) when b, t known, Pa
};

/// Fits the compliance and inverts continuum and chain. Throws InputError on bad values,
/// naming the row and column of a value whose products overflow, and on any result that
/// is not a finite number.
BendingIdentification identify_bending(const CantileverData& data, double length, int segments,
                                       std::optional<double> width = std::nullopt,
                                       std::optional<double> thickness = std::nullopt);

}  // namespace finseg

#include "solvers/single_precision_factor.hpp"

#include <cholmod.h>

#include <algorithm>
#include <cfloat>
#include <cmath>

extern "C" {
// The BLAS under CHOLMOD (libblas.so.3, CMakeLists.txt), single precision.
void sgemv_(const char* trans, const int* m, const int* n, const float* alpha, const float* a,
            const int* lda, const float* x, const int* incx, const float* beta, float* y,
            const int* incy);
void strsv_(const char* uplo, const char* trans, const char* diag, const int* n, const float* a,
            const int* lda, float* x, const int* incx);
}

namespace finseg {
namespace {

std::vector<int> copied(const void* p, std::size_t count) {
  const int* v = static_cast<const int*>(p);
  return std::vector<int>(v, v + count);
}

}  // namespace

SinglePrecisionFactor SinglePrecisionFactor::of(const cholmod_factor& L) {
  SinglePrecisionFactor f;
  if (L.is_super == 0 || L.is_ll == 0 || L.xtype != CHOLMOD_REAL || L.itype != CHOLMOD_INT ||
      L.dtype != CHOLMOD_DOUBLE || L.n == 0 || L.Perm == nullptr) {
    return f;
  }
  const std::size_t nsuper = L.nsuper;
  f.super_ = copied(L.super, nsuper + 1);
  f.pi_ = copied(L.pi, nsuper + 1);
  f.px_ = copied(L.px, nsuper + 1);
  f.rows_ = copied(L.s, static_cast<std::size_t>(f.pi_.back()));
  f.perm_ = copied(L.Perm, L.n);
  const auto* x = static_cast<const double*>(L.x);
  f.values_.resize(static_cast<std::size_t>(f.px_.back()));
  int held = 1;  // one pass over L (about 200 MB at 10^4 segments), vectorised
  for (std::size_t i = 0; i < f.values_.size(); ++i) {
    held &= static_cast<int>(std::abs(x[i]) <= FLT_MAX);
    f.values_[i] = static_cast<float>(std::clamp(x[i], -double{FLT_MAX}, double{FLT_MAX}));
  }
  if (held == 0) return SinglePrecisionFactor();
  int widest = 0;
  for (int s = 0; s < static_cast<int>(nsuper); ++s) {
    const Supernode sn = f.supernode(s);
    for (int j = 0; j < sn.cols; ++j) {
      if (!(sn.L[j * (sn.rows + 1)] >= FLT_MIN)) return SinglePrecisionFactor();
    }
    widest = std::max(widest, sn.rows);
  }
  f.n_ = static_cast<int>(L.n);
  f.y_.resize(L.n);
  f.t_.resize(static_cast<std::size_t>(widest));
  return f;
}

SinglePrecisionFactor::Supernode SinglePrecisionFactor::supernode(int s) const {
  const int cols = super_[s + 1] - super_[s], rows = pi_[s + 1] - pi_[s];
  return {super_[s], cols, rows, values_.data() + px_[s], rows_.data() + pi_[s] + cols};
}

bool SinglePrecisionFactor::solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) const {
  if (!valid() || b.size() != n_) return false;
  const int one = 1;
  const float plus = 1, minus = -1, zero = 0;
  float* y = y_.data();
  float* t = t_.data();
  for (int k = 0; k < n_; ++k) y[k] = static_cast<float>(b[perm_[k]]);
  const int nsuper = static_cast<int>(super_.size()) - 1;
  // L y = P b, supernode by supernode: the diagonal block, then the rows below it.
  for (int s = 0; s < nsuper; ++s) {
    const Supernode sn = supernode(s);
    strsv_("L", "N", "N", &sn.cols, sn.L, &sn.rows, y + sn.first, &one);
    const int below = sn.rows - sn.cols;
    if (below == 0) continue;
    sgemv_("N", &below, &sn.cols, &plus, sn.L + sn.cols, &sn.rows, y + sn.first, &one, &zero, t,
           &one);
    for (int i = 0; i < below; ++i) y[sn.below[i]] -= t[i];
  }
  // L^T z = y, supernodes in reverse.
  for (int s = nsuper - 1; s >= 0; --s) {
    const Supernode sn = supernode(s);
    const int below = sn.rows - sn.cols;
    if (below > 0) {
      for (int i = 0; i < below; ++i) t[i] = y[sn.below[i]];
      sgemv_("T", &below, &sn.cols, &minus, sn.L + sn.cols, &sn.rows, t, &one, &plus, y + sn.first,
             &one);
    }
    strsv_("L", "T", "N", &sn.cols, sn.L, &sn.rows, y + sn.first, &one);
  }
  x.resize(n_);
  for (int k = 0; k < n_; ++k) x[perm_[k]] = y[k];
  return x.allFinite();
}

}  // namespace finseg

// Folds and multiplier crossings along a bright-breather branch (branch_bifurcations.hpp).
#include "lrchain/sim/bright/branch_bifurcations.hpp"

#include <algorithm>
#include <cmath>
#include <complex>

namespace lrchain::sim::bright {

namespace {

// The fold between samples a and b (a.tangent_omega and b.tangent_omega of opposite signs): the zero of
// the derivative of the cubic Hermite interpolant of omega_b(s) with values and slopes at both ends.
BranchBifurcation locate_fold(const BranchSample& a, const BranchSample& b, Index index) {
  const double h = b.arclength - a.arclength;
  const double d0 = a.tangent_omega * h, d1 = b.tangent_omega * h, dw = b.omega_b - a.omega_b;
  // p(t) = omega_a + d0 t + c2 t^2 + c3 t^3 on t in [0, 1]; p'(t) = d0 + 2 c2 t + 3 c3 t^2.
  const double c2 = 3 * dw - 2 * d0 - d1, c3 = -2 * dw + d0 + d1;
  double t = d0 / (d0 - d1);  // linear interpolation of the slope: the root when c3 = 0
  if (std::abs(c3) > 1e-14 * (std::abs(c2) + std::abs(d0))) {
    const double qa = 3 * c3, qb = 2 * c2, disc = std::max(0.0, qb * qb - 4 * qa * d0);
    const double r1 = (-qb + std::sqrt(disc)) / (2 * qa), r2 = (-qb - std::sqrt(disc)) / (2 * qa);
    t = std::abs(r1 - 0.5) <= std::abs(r2 - 0.5) ? r1 : r2;  // the root inside [0, 1]
  }
  t = std::clamp(t, 0.0, 1.0);
  BranchBifurcation f{"fold", index, a.omega_b + t * (d0 + t * (c2 + t * c3)),
                      a.norm_squared + t * (b.norm_squared - a.norm_squared), std::min(a.omega_b, b.omega_b),
                      std::max(a.omega_b, b.omega_b)};
  return f;
}

BranchBifurcation bracket(const char* kind, const BranchSample& a, const BranchSample& b, Index index) {
  return {kind, index, 0.5 * (a.omega_b + b.omega_b), 0.5 * (a.norm_squared + b.norm_squared),
          std::min(a.omega_b, b.omega_b), std::max(a.omega_b, b.omega_b)};
}

}  // namespace

Index real_multipliers_beyond(const BrightFloquet& f, int sign, double tolerance) {
  std::vector<std::complex<double>> rest = f.multipliers.multipliers;
  for (const auto& t : f.trivial) {  // each trivial multiplier once
    const auto it = std::find(rest.begin(), rest.end(), t);
    if (it != rest.end()) rest.erase(it);
  }
  Index count = 0;
  for (const auto& l : rest)
    if (std::abs(l.imag()) <= dark::FloquetOptions{}.real_tolerance * std::abs(l) && sign * l.real() > 1 + tolerance) ++count;
  return count;
}

std::vector<BranchBifurcation> branch_bifurcations(const std::vector<BranchSample>& samples) {
  std::vector<BranchBifurcation> found;
  for (std::size_t k = 1; k < samples.size(); ++k) {
    const BranchSample &a = samples[k - 1], &b = samples[k];
    const Index index = Index(k - 1);
    if ((a.tangent_omega > 0) != (b.tangent_omega > 0)) found.push_back(locate_fold(a, b, index));
    if (a.real_unstable && b.real_unstable && *a.real_unstable != *b.real_unstable)
      found.push_back(bracket("branch_point", a, b, index));
    if (a.period_doubling && b.period_doubling && *a.period_doubling != *b.period_doubling)
      found.push_back(bracket("period_doubling", a, b, index));
    if (a.oscillatory && b.oscillatory && !*a.oscillatory && *b.oscillatory)
      found.push_back(bracket("krein_collision", a, b, index));
  }
  return found;
}

}  // namespace lrchain::sim::bright

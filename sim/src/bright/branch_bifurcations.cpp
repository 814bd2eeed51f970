// Folds and multiplier crossings along a bright-breather branch (branch_bifurcations.hpp).
#include "lrchain/sim/bright/branch_bifurcations.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>

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
                      std::max(a.omega_b, b.omega_b), false, 0, std::nullopt};
  return f;
}

BranchBifurcation bracket(const char* kind, const BranchSample& a, const BranchSample& b, Index index) {
  return {kind, index, 0.5 * (a.omega_b + b.omega_b), 0.5 * (a.norm_squared + b.norm_squared),
          std::min(a.omega_b, b.omega_b), std::max(a.omega_b, b.omega_b), false, 0, std::nullopt};
}

// The multipliers of f without its trivial ones (each removed once).
std::vector<std::complex<double>> nontrivial_multipliers(const BrightFloquet& f) {
  std::vector<std::complex<double>> rest = f.multipliers.multipliers;
  for (const auto& t : f.trivial) {
    const auto it = std::find(rest.begin(), rest.end(), t);
    if (it != rest.end()) rest.erase(it);
  }
  return rest;
}

}  // namespace

Index real_multipliers_beyond(const BrightFloquet& f, int sign, double tolerance) {
  Index count = 0;
  for (const auto& l : nontrivial_multipliers(f))
    if (std::abs(l.imag()) <= dark::FloquetOptions{}.real_tolerance * std::abs(l) && sign * l.real() > 1 + tolerance) ++count;
  return count;
}

Index multipliers_beyond_two_thirds(const BrightFloquet& f) {
  Index count = 0;
  for (const auto& l : nontrivial_multipliers(f))
    if (std::abs(std::arg(l)) > 2 * std::numbers::pi / 3) ++count;
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
    if (a.period_tripling && b.period_tripling && *a.period_tripling != *b.period_tripling)
      found.push_back(bracket("period_tripling", a, b, index));
    if (a.oscillatory && b.oscillatory && !*a.oscillatory && *b.oscillatory)
      found.push_back(bracket("krein_collision", a, b, index));
  }
  return found;
}

Index crossing_indicator(const std::string& kind, const BrightFloquet& f, double unit_tolerance) {
  if (kind == "branch_point") return real_multipliers_beyond(f, +1, unit_tolerance);
  if (kind == "period_doubling") return real_multipliers_beyond(f, -1, unit_tolerance);
  if (kind == "period_tripling") return multipliers_beyond_two_thirds(f);
  return f.multipliers.oscillatory ? 1 : 0;
}

std::complex<double> crossing_multiplier(const std::string& kind, const BrightFloquet& f) {
  const std::vector<std::complex<double>> rest = nontrivial_multipliers(f);
  if (rest.empty()) return {1, 0};
  const std::complex<double> target = kind == "branch_point"      ? std::complex<double>(1, 0)
                                      : kind == "period_doubling" ? std::complex<double>(-1, 0)
                                                                  : std::polar(1.0, 2 * std::numbers::pi / 3);
  // |lambda - target| for a crossing point, -|lambda| (largest modulus first) for a Krein collision; of a
  // pair (lambda, 1/conj(lambda)) the one outside the circle, in the upper half plane off the real axis
  const auto score = [&](const std::complex<double>& l) {
    if (l.imag() < 0 && kind != "branch_point" && kind != "period_doubling") return 1e300;
    if (kind == "krein_collision" && std::abs(l.imag()) <= dark::FloquetOptions{}.real_tolerance * std::abs(l)) return 1e299;
    const double inside = std::abs(l) < 1 - 1e-9 ? 1e6 : 0;
    return inside + (kind == "krein_collision" ? -std::abs(l) : std::abs(l - target));
  };
  return *std::min_element(rest.begin(), rest.end(),
                           [&](const auto& x, const auto& y) { return score(x) < score(y); });
}

// Bisection in the continued parameter: the end with a's indicator moves to the midpoint while the indicator there is
// a's; the other end keeps the change (b's indicator, or another value: the change lies between a and it).
void locate_crossing(BranchBifurcation& b, double p_a, const Eigen::VectorXd& z_a, const BrightFloquet& fa,
                     double p_b, const Eigen::VectorXd& z_b, const BrightFloquet& fb, const CrossingSolver& solve,
                     double unit_tolerance, double tolerance) {
  const Index before = crossing_indicator(b.kind, fa, unit_tolerance);
  double lo = p_a, hi = p_b;
  Eigen::VectorXd z_lo = z_a, z_hi = z_b;
  BrightFloquet f_hi = fb;
  double norm_hi = z_b.squaredNorm();
  while (std::abs(hi - lo) > tolerance) {
    const double mid = 0.5 * (lo + hi);
    const Eigen::VectorXd guess = z_lo + (z_hi - z_lo) * ((mid - lo) / (hi - lo));  // Z(0) linear in p
    const std::optional<CrossingSolution> s = solve(mid, guess);
    if (!s) return;  // not located: the bracket of the branch points stands
    if (crossing_indicator(b.kind, s->floquet, unit_tolerance) == before) {
      lo = mid, z_lo = s->z0;
    } else {
      hi = mid, z_hi = s->z0, f_hi = s->floquet, norm_hi = s->norm_squared;
    }
  }
  b.omega_b = 0.5 * (lo + hi);
  b.location_error = 0.5 * std::abs(hi - lo);
  b.multiplier = crossing_multiplier(b.kind, f_hi);
  b.norm_squared = norm_hi;
  b.located = true;
}

}  // namespace lrchain::sim::bright

// Linear bands of a model lattice and the bright breather's non-resonance check (linear_bands.hpp).
#include "lrchain/sim/bright/linear_bands.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <boost/math/tools/minima.hpp>
#include <fmt/format.h>

#include "lrchain/errors.hpp"

namespace lrchain::sim::bright {

namespace {

// omega(theta) of `branch`, or NaN where the branch has no positive frequency.
double branch_omega(const Model& model, Index branch, double theta) {
  NlsCoefficients c;
  if (!coefficients_at(model.definition(), model.inputs().data(), branch, theta, c)) return NAN;
  return c.omega;
}

// The extremum of sign s (+1 max, -1 min) of omega near the sample theta_k, refined in [theta_k-1, theta_k+1].
double refined(const Model& model, Index branch, double a, double b, double sign) {
  const auto f = [&](double theta) {
    const double w = branch_omega(model, branch, theta);
    return std::isfinite(w) ? -sign * w : 0.0;
  };
  const auto found = boost::math::tools::brent_find_minima(f, a, b, 52);
  return -sign * found.second;
}

}  // namespace

std::vector<LinearBand> linear_bands(const Model& model, Index samples) {
  std::vector<LinearBand> bands;
  const auto& names = model.definition().branch_names;
  const double step = std::numbers::pi / double(samples);
  for (Index branch = 0; branch < Index(names.size()); ++branch) {
    std::vector<double> omega(std::size_t(samples) + 1);
    for (Index k = 0; k <= samples; ++k) omega[std::size_t(k)] = branch_omega(model, branch, step * double(k));
    if (!std::isfinite(omega[0])) omega[0] = 0;  // an acoustic branch: omega(0) = 0
    LinearBand band{names[std::size_t(branch)], INFINITY, -INFINITY};
    for (Index k = 0; k <= samples; ++k) {
      const double w = omega[std::size_t(k)];
      if (!std::isfinite(w)) continue;
      band.lowest = std::min(band.lowest, w);
      band.highest = std::max(band.highest, w);
      if (k == 0 || k == samples) continue;  // the edges are exact samples
      const double before = omega[std::size_t(k - 1)], after = omega[std::size_t(k + 1)];
      if (w >= before && w >= after) band.highest = std::max(band.highest, refined(model, branch, step * double(k - 1), step * double(k + 1), 1));
      if (w <= before && w <= after) band.lowest = std::min(band.lowest, refined(model, branch, step * double(k - 1), step * double(k + 1), -1));
    }
    if (!std::isfinite(band.lowest)) continue;  // no real frequency anywhere
    bands.push_back(band);
  }
  return bands;
}

std::optional<Resonance> first_resonance(const std::vector<LinearBand>& bands, double omega_b) {
  double top = 0;
  for (const auto& band : bands) top = std::max(top, band.highest);
  for (Index k = 1; double(k) * omega_b <= top; ++k)
    for (const auto& band : bands)
      if (double(k) * omega_b >= band.lowest && double(k) * omega_b <= band.highest) return Resonance{k, band};
  return std::nullopt;
}

std::pair<double, double> non_resonant_window(const std::vector<LinearBand>& bands, double omega_b) {
  double low = 0, high = INFINITY, top = 0;
  for (const auto& band : bands) top = std::max(top, band.highest);
  // k omega in [lowest, highest] <=> omega in [lowest / k, highest / k]; k beyond top / omega_b + 1
  // gives intervals below those of smaller k that lie below omega_b.
  for (Index k = 1; double(k) <= top / omega_b + 1; ++k)
    for (const auto& band : bands) {
      const double from = band.lowest / double(k), to = band.highest / double(k);
      if (to < omega_b) low = std::max(low, to);
      if (from > omega_b) high = std::min(high, from);
    }
  return {low, high};
}

void check_non_resonance(const std::vector<LinearBand>& bands, double omega_b) {
  const auto r = first_resonance(bands, omega_b);
  if (!r) return;
  const std::string band = fmt::format("the linear band of branch {}, [{:.10g}, {:.10g}]", r->band.branch,
                                       r->band.lowest, r->band.highest);
  if (r->harmonic == 1)
    throw InvalidParameter("omega_b", fmt::format("omega_b = {:.10g} lies inside {}: a bright breather's frequency must "
                                                  "lie outside every band (above the top one or in a gap)", omega_b, band));
  throw InvalidParameter("omega_b", fmt::format("its harmonic {} omega_b = {:.10g} lies inside {}: the breather would "
                                                "radiate into it, so no exact localized breather exists at omega_b = {:.10g}",
                                                r->harmonic, double(r->harmonic) * omega_b, band, omega_b));
}

}  // namespace lrchain::sim::bright

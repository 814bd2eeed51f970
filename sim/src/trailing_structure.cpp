// Secondary structure left behind a moving bright breather (Sec. 4.2, Fig. 11).
#include "lrchain/sim/trailing_structure.hpp"

#include <algorithm>
#include <cmath>

#include "lrchain/sim/least_squares.hpp"

namespace lrchain::sim {

TrailingStructure track_trailing_structure(const SpaceTime& field, const std::vector<double>& centre_t,
                                           const std::vector<double>& centre_x, std::span<const double> x,
                                           std::span<const double> y, Index x_first,
                                           const TrailingStructureOptions& opt) {
  TrailingStructure r;
  if (!(opt.fit_start > 0) || field.sites == 0 || centre_t.empty()) return r;
  std::vector<double> fit_t, fit_c;
  const Index sites = field.sites;
  for (std::size_t row = 0; row < field.times.size(); ++row) {
    const double t = field.times[row];
    if (t < opt.fit_start) continue;
    // X(t) at the nearest recorded time.
    const auto it = std::lower_bound(centre_t.begin(), centre_t.end(), t);
    const std::size_t k = it == centre_t.end() ? centre_t.size() - 1 : std::size_t(it - centre_t.begin());
    const double X = centre_x[k];
    const float* e = field.values.data() + static_cast<Index>(row) * sites;
    Index best = -1;
    for (Index i = 0; i < sites; ++i) {
      const Index n = field.first_label + i;
      if (double(n) >= X - opt.gap || std::abs(n) > opt.far_end) continue;
      if (best < 0 || e[i] > e[best]) best = i;
    }
    if (best < 0) continue;
    double num = 0, den = 0;
    for (Index i = std::max<Index>(0, best - opt.half_window); i <= std::min(sites - 1, best + opt.half_window); ++i) {
      num += double(field.first_label + i) * e[i];
      den += e[i];
    }
    if (!(den > 0)) continue;
    fit_t.push_back(t);
    fit_c.push_back(num / den);
    r.max_energy_density = e[best];
  }
  if (fit_t.size() < 2) return r;
  r.found = true;
  r.speed = least_squares_slope(fit_t, fit_c);
  r.centre_end = fit_c.back();
  // Final strains around the final centre: amplitude and y/x of the oscillating parts.
  const Index count = std::min(Index(x.size()), Index(y.size()));
  const Index c = Index(std::lround(r.centre_end)) - x_first;
  const Index lo = std::max<Index>(0, c - opt.half_window), hi = std::min(count - 1, c + opt.half_window);
  if (hi <= lo) return r;
  double mx = 0, my = 0;
  for (Index i = lo; i <= hi; ++i) { mx += x[i]; my += y[i]; }
  mx /= double(hi - lo + 1);
  my /= double(hi - lo + 1);
  double sxx = 0, sxy = 0;
  for (Index i = lo; i <= hi; ++i) {
    sxx += (x[i] - mx) * (x[i] - mx);
    sxy += (x[i] - mx) * (y[i] - my);
    r.max_abs_x = std::max(r.max_abs_x, std::abs(x[i]));
  }
  r.y_over_x = sxx > 0 ? sxy / sxx : 0;
  return r;
}

}  // namespace lrchain::sim

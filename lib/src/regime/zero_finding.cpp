#include "lrchain/regime/zero_finding.hpp"

#include <algorithm>
#include <boost/math/tools/minima.hpp>
#include <boost/math/tools/roots.hpp>
#include <cmath>
#include <cstdint>
#include <limits>

namespace lrchain::regime {

double solve_bracketed(const std::function<double(double)>& f, double a, double b, double fa,
                       double fb, double x_tolerance) {
  if (fa == 0.0) return a;
  if (fb == 0.0) return b;
  std::uintmax_t max_iter = 200;
  const auto done = [x_tolerance](double lo, double hi) { return std::abs(hi - lo) <= x_tolerance; };
  const auto r = boost::math::tools::toms748_solve(f, a, b, fa, fb, done, max_iter);
  return 0.5 * (r.first + r.second);
}

std::vector<double> find_zeros(const std::function<double(double)>& f, std::span<const double> xs,
                               std::span<const double> fs, double x_tolerance) {
  std::vector<double> zeros;
  const std::size_t n = xs.size();
  for (std::size_t i = 0; i + 1 < n; ++i) {
    const double f0 = fs[i], f1 = fs[i + 1];
    if (std::isnan(f0) || std::isnan(f1)) continue;
    if (f0 == 0.0) {
      zeros.push_back(xs[i]);
      continue;
    }
    if ((f0 < 0.0) != (f1 < 0.0) && f1 != 0.0) {
      zeros.push_back(solve_bracketed(f, xs[i], xs[i + 1], f0, f1, x_tolerance));
    } else if (i >= 1 && f1 != 0.0) {
      // Interior local minimum of |f| at xs[i] without sign change: probe for a hidden pair.
      const double fm = fs[i - 1];
      if (std::isnan(fm) || fm == 0.0 || (fm < 0.0) != (f0 < 0.0)) continue;
      if (!(std::abs(f0) < std::abs(fm) && std::abs(f0) <= std::abs(f1))) continue;
      const double s = f0 > 0.0 ? 1.0 : -1.0;
      const auto g = [&](double x) { return s * f(x); };
      std::uintmax_t it = 100;
      const auto m = boost::math::tools::brent_find_minima(
          g, xs[i - 1], xs[i + 1], std::numeric_limits<double>::digits / 2, it);
      if (m.second < 0.0) {
        const double xm = m.first, fxm = s * m.second;
        zeros.push_back(solve_bracketed(f, xs[i - 1], xm, fm, fxm, x_tolerance));
        zeros.push_back(solve_bracketed(f, xm, xs[i + 1], fxm, f1, x_tolerance));
      }
    }
  }
  if (n > 0 && fs[n - 1] == 0.0) zeros.push_back(xs[n - 1]);
  std::sort(zeros.begin(), zeros.end());
  zeros.erase(std::unique(zeros.begin(), zeros.end(),
                          [&](double a, double b) { return b - a <= x_tolerance; }),
              zeros.end());
  return zeros;
}

std::vector<double> find_zeros(const std::function<double(double)>& f, double a, double b,
                               const ZeroFindingOptions& options) {
  const Index n = std::max<Index>(options.samples, 2);
  std::vector<double> xs(n), fs(n);
  for (Index i = 0; i < n; ++i) {
    xs[i] = i == n - 1 ? b : a + (b - a) * i / (n - 1);
    fs[i] = f(xs[i]);
  }
  return find_zeros(f, xs, fs, options.x_tolerance);
}

}  // namespace lrchain::regime

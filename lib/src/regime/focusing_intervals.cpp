#include "lrchain/regime/focusing_intervals.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "lrchain/errors.hpp"
#include "lrchain/regime/zero_finding.hpp"

namespace lrchain::regime {

// Sec. 3.3: zeros of omega'', of the h_tilde numerator and of both non-resonance factors on
// (0, pi], then the sign of their product on each piece between consecutive zeros.
RegimeStructure regime_structure(const RegimeFunctions& f, const IntervalOptions& options) {
  if (options.samples < 8) throw InvalidParameter("samples", "must be >= 8");
  const double pi = std::numbers::pi;
  const int n = options.samples;
  std::vector<double> xs(n);
  std::vector<RegimeSample> samples(n);
  for (int i = 0; i < n; ++i) {
    xs[i] = i == n - 1 ? pi : pi * (i + 1) / n;
    samples[i] = f(xs[i]);
  }
  RegimeStructure out;
  std::vector<double> fs(n);
  for (BoundaryCause cause : kSmoothCauses) {
    for (int i = 0; i < n; ++i) fs[i] = samples[i][cause];
    const auto g = [&f, cause](double theta) { return f(theta)[cause]; };
    for (double z : find_zeros(g, xs, fs, options.x_tolerance))
      if (z < pi - 1e-10) out.roots.push_back({z, cause});  // theta = pi is the band edge
  }
  std::sort(out.roots.begin(), out.roots.end(),
            [](const BoundaryRoot& a, const BoundaryRoot& b) { return a.theta < b.theta; });

  // Breakpoints: 0, every cluster of zeros (closer than 10 tolerances), pi.
  struct Break {
    double theta;
    BoundaryCause cause;
  };
  std::vector<Break> breaks{{0.0, BoundaryCause::band_edge}};
  for (const auto& r : out.roots) {
    if (breaks.size() > 1 && r.theta - breaks.back().theta <= 10 * options.x_tolerance) continue;
    breaks.push_back({r.theta, r.cause});
  }
  breaks.push_back({pi, BoundaryCause::band_edge});

  bool open = false;
  FocusingInterval cur;
  for (std::size_t k = 0; k + 1 < breaks.size(); ++k) {
    const double a = breaks[k].theta, b = breaks[k + 1].theta;
    // Sign on the piece: at the first sample inside it if any (cheap, away from the zeros),
    // otherwise at its midpoint.
    const auto it = std::upper_bound(xs.begin(), xs.end(), a);
    const bool focusing = (it != xs.end() && *it < b) ? samples[it - xs.begin()].focusing()
                                                      : f(0.5 * (a + b)).focusing();
    if (focusing && !open) {
      open = true;
      cur.lo = a;
      cur.lo_cause = breaks[k].cause;
    } else if (!focusing && open) {
      open = false;
      cur.hi = a;
      cur.hi_cause = breaks[k].cause;
      out.intervals.push_back(cur);
    }
  }
  if (open) {
    cur.hi = pi;
    cur.hi_cause = BoundaryCause::band_edge;
    out.intervals.push_back(cur);
  }
  return out;
}

std::vector<FocusingInterval> focusing_intervals(const Params& p, Branch b,
                                                 const IntervalOptions& options) {
  return regime_structure(regime_functions(p, b), options).intervals;
}

}  // namespace lrchain::regime

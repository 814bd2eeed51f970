// Localization check and measures of a bright breather's Z(0) (bright_profile.hpp).
#include "lrchain/sim/bright/bright_profile.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

namespace lrchain::sim::bright {

BrightProfile inspect_bright_profile(const Eigen::VectorXd& z0, Index sites, const BrightProfileOptions& o) {
  BrightProfile p;
  const Index variables = z0.size() / sites, centre = (sites - 1) / 2;
  const auto x0 = z0.head(sites).cwiseAbs();
  p.peak = x0.maxCoeff(&p.peak_site);
  p.norm_squared = z0.squaredNorm();
  const double fourth = x0.array().pow(4).sum();
  p.width = fourth > 0 ? std::pow(x0.squaredNorm(), 2) / fourth : 0.0;
  if (!(p.peak > 0)) {
    p.reason = "the solution is at rest";
    return p;
  }
  // The far quarter: sites at ring distance > 3 sites/8 from the centre.
  double tail = 0;
  for (Index v = 0; v < variables; ++v)
    for (Index i = 0; i < sites; ++i)
      if (std::abs(i - centre) > 3 * sites / 8) tail = std::max(tail, std::abs(z0(v * sites + i)));
  p.tail = tail / p.peak;
  if (p.tail > o.tail_tolerance) {
    p.reason = fmt::format("not localized: |Z| on the ring's far quarter reaches {:.3g} of the peak (allowed {:g}); "
                           "use more sites or omega_b farther from the band edge", p.tail, o.tail_tolerance);
    return p;
  }
  if (std::abs(p.peak_site - centre) > 1 && std::abs(double(p.peak_site - centre) - o.centre_position) > 1) {
    p.reason = fmt::format("the maximum of |x_0| is at site {}, not at the centre {} (a breather centred elsewhere)",
                           p.peak_site, double(centre) + o.centre_position);
    return p;
  }
  // Envelope over neighbour pairs, walking outward on each side of the centre.
  for (const Index direction : {Index(-1), Index(1)}) {
    double previous = p.peak;
    for (Index d = 1; centre + direction * (d + 1) >= 0 && centre + direction * (d + 1) < sites; d += 2) {
      const double envelope = std::max(x0(centre + direction * d), x0(centre + direction * (d + 1)));
      if (envelope > previous + o.shape_tolerance * p.peak) {
        p.reason = fmt::format("a second maximum of |x_0| at site {} ({:.3g} of the peak): not one hump at the centre",
                               centre + direction * d, envelope / p.peak);
        return p;
      }
      previous = envelope;
    }
  }
  p.localized = true;
  return p;
}

double relative_profile_difference(const Eigen::VectorXd& z, const Eigen::VectorXd& reference) {
  const double scale = z.cwiseAbs().maxCoeff();
  return scale > 0 ? (z - reference).cwiseAbs().maxCoeff() / scale : INFINITY;
}

}  // namespace lrchain::sim::bright

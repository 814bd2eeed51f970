// The anti-continuum start of a bright breather (anti_continuum.hpp).
#include "lrchain/sim/bright/anti_continuum.hpp"

#include <cmath>

#include <fmt/format.h>

#include "lrchain/errors.hpp"

namespace lrchain::sim::bright {

namespace {

constexpr int kScan = 80;                        // amplitudes scanned, logarithmically spaced
constexpr double kSmallest = 1e-4, kLargest = 100;

// The amplitude x0 > 0 with which the oscillator at `site` (field 0), started at rest from sign x0 with
// every other site at rest, has xdot(T_b/2) = 0 at omega_b: the smallest root over the scan, bisected.
// NaN when none. At coupling 0 the other sites stay at rest, so this is one oscillator's half period.
double oscillator_amplitude(const dark::DarkShooting& uncoupled, double omega_b, Index site, double sign) {
  Eigen::VectorXd z = Eigen::VectorXd::Zero(uncoupled.unknowns()), residual;
  const auto half_period_velocity = [&](double x0) {
    z(site) = sign * x0;
    uncoupled.evaluate(z, omega_b, residual, nullptr);
    return residual(site);
  };
  double previous_x = NAN, previous_v = NAN;
  for (int k = 0; k < kScan; ++k) {
    const double x = kSmallest * std::pow(kLargest / kSmallest, double(k) / (kScan - 1));
    const double v = half_period_velocity(x);
    if (!std::isfinite(v)) break;  // escaped over a barrier (a soft potential): no larger amplitude either
    if (std::isfinite(previous_v) && (v == 0 || (v > 0) != (previous_v > 0))) {
      double lo = previous_x, hi = x, v_lo = previous_v;
      for (int i = 0; i < 200 && hi - lo > 1e-14 * hi; ++i) {
        const double mid = 0.5 * (lo + hi), v_mid = half_period_velocity(mid);
        if ((v_mid > 0) == (v_lo > 0)) lo = mid, v_lo = v_mid;
        else hi = mid;
      }
      return 0.5 * (lo + hi);
    }
    previous_x = x, previous_v = v;
  }
  return NAN;
}

}  // namespace

AntiContinuumOrbit anti_continuum_orbit(const dark::DarkShooting& uncoupled, double omega_b, Index sites, bool bond,
                                        bool staggered) {
  const Index centre = (sites - 1) / 2;
  AntiContinuumOrbit orbit;
  orbit.z0 = Eigen::VectorXd::Zero(uncoupled.unknowns());
  orbit.amplitude = oscillator_amplitude(uncoupled, omega_b, centre, 1.0);
  // The partner of a bond-centred pair starts from -x1 when staggered: its own amplitude, since the
  // on-site potential need not be even (x0 and x1 differ when it has a quadratic force term).
  const double partner = bond ? oscillator_amplitude(uncoupled, omega_b, centre + 1, staggered ? -1.0 : 1.0) : 0.0;
  if (!std::isfinite(orbit.amplitude) || !std::isfinite(partner))
    throw InvalidParameter("omega_b", fmt::format("no oscillator of the uncoupled lattice (coupling 0) started at rest "
                                                  "from an amplitude in [{:g}, {:g}]{} oscillates at omega_b = {:.10g}",
                                                  kSmallest, kLargest, bond && staggered ? " (or its negative)" : "",
                                                  omega_b));
  orbit.z0(centre) = orbit.amplitude;
  if (bond) orbit.z0(centre + 1) = staggered ? -partner : partner;
  return orbit;
}

}  // namespace lrchain::sim::bright

#include "lrchain/regime/regime_map.hpp"

#include <cmath>
#include <numbers>

#include "lrchain/coefficients.hpp"
#include "lrchain/errors.hpp"
#include "lrchain/regime/frequency_band.hpp"

namespace lrchain::regime {

namespace {
std::int8_t pixel(const NlsCoefficients& c) {
  switch (c.regime) {
    case Regime::focusing: return PixelRegime::focusing;
    case Regime::defocusing: return PixelRegime::defocusing;
    case Regime::singular: return PixelRegime::singular;
    // omega'' h_tilde = 0 exactly (e.g. theta = 0 optical): not focusing (focusing needs < 0).
    case Regime::degenerate: return PixelRegime::defocusing;
  }
  return PixelRegime::singular;
}
}  // namespace

// Fig. 2: sign(omega'' h_tilde) over (rho, theta); K2..K4 depend on delta0 only.
RegimeMap theta_rho_map(const Params& base, Branch b, const GridAxis& rho, const GridAxis& theta) {
  validate(base);
  validate(rho, "rho");
  validate(theta, "theta");
  if (!(rho.lo > 0.0)) throw InvalidParameter("rho", "range must lie in rho > 0");
  if (!(theta.lo > 0.0 || (b == Branch::optical && theta.lo >= 0.0)) || theta.hi > std::numbers::pi + 1e-12)
    throw InvalidParameter("theta", "range must lie in (0, pi] ([0, pi] for optical)");
  RegimeMap map{b, rho, theta, std::vector<std::int8_t>(static_cast<std::size_t>(rho.n) * theta.n)};
  const TaylorCoefficients K = taylor_coefficients(base);
  const int nx = rho.n, ny = theta.n;
#pragma omp parallel for schedule(static)
  for (int i = 0; i < nx; ++i) {
    Params p = base;
    p.rho = rho.at(i);
    for (int j = 0; j < ny; ++j)
      map.values[static_cast<std::size_t>(j) * nx + i] =
          pixel(coefficients_unchecked(p, K, b, theta.at(j)));
  }
  return map;
}

// Figs. 4-5: per delta0 the band of branch b, omega -> theta by theta_of_omega.
RegimeMap delta0_omega_map(const Params& base, Branch b, const GridAxis& delta0,
                           const GridAxis& omega) {
  validate(base);
  validate(delta0, "delta0");
  validate(omega, "omega");
  if (!(delta0.lo > 0.0)) throw InvalidParameter("delta0", "range must lie in delta0 > 0");
  if (!(omega.lo >= 0.0)) throw InvalidParameter("omega", "range must lie in omega >= 0");
  RegimeMap map{b, delta0, omega,
                std::vector<std::int8_t>(static_cast<std::size_t>(delta0.n) * omega.n)};
  const int nx = delta0.n, ny = omega.n;
#pragma omp parallel for schedule(static)
  for (int i = 0; i < nx; ++i) {
    Params p = base;
    p.delta0 = delta0.at(i);
    const TaylorCoefficients K = taylor_coefficients(p);
    const FrequencyBand band = frequency_band(p, b);
    for (int j = 0; j < ny; ++j) {
      const double w = omega.at(j);
      std::int8_t v = PixelRegime::outside;
      if (w > band.lo && w <= band.hi) {
        const double theta = theta_of_omega(K.K2, p.kappa, p.rho, w);
        if (theta > 0.0) v = pixel(coefficients_unchecked(p, K, b, theta));
      }
      map.values[static_cast<std::size_t>(j) * nx + i] = v;
    }
  }
  return map;
}

}  // namespace lrchain::regime

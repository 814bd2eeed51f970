// Energy density (eq:edensity) and energy centre (eq:ectr).
#include "lrchain/sim/energy.hpp"

#include <algorithm>

namespace lrchain::sim {

void energy_density(const DisplacementLattice& lattice, const State& s, double t, double* e,
                    double* r) {
  const auto& L = lattice.layout();
  const std::size_t n = L.sites;
  const auto& p = lattice.params();
  const double* u = L.primary(s);
  const double* v = L.secondary(s);
  const double* du = L.primary_rate(s);
  const double* dv = L.secondary_rate(s);
  lattice.bond_strains(u, t, r);
  bond_energies_from_strains(lattice.law(), r, r, n + 1);  // V(r_j)
  for (std::size_t i = 0; i < n; ++i) {
    const double w = u[i] - v[i];
    e[i] = 0.5 * du[i] * du[i] + 0.5 * p.rho * dv[i] * dv[i] + 0.5 * p.kappa * w * w +
           0.5 * (r[i] + r[i + 1]);
  }
}

double energy_centre(const double* e, std::size_t sites, std::size_t m) {
  const std::size_t peak = static_cast<std::size_t>(std::max_element(e, e + sites) - e);
  const std::size_t lo = peak >= m ? peak - m : 0;
  const std::size_t hi = std::min(sites - 1, peak + m);
  double num = 0, den = 0;
  for (std::size_t i = lo; i <= hi; ++i) {
    num += static_cast<double>(i) * e[i];
    den += e[i];
  }
  return den != 0 ? num / den : static_cast<double>(peak);
}

}  // namespace lrchain::sim

// Energy density (eq:edensity) and energy centre (eq:ectr).
#include "lrchain/sim/energy.hpp"

#include <algorithm>

namespace lrchain::sim {

void energy_density(const DisplacementLattice& lattice, const State& s, double t, std::span<double> e,
                    std::span<double> r) {
  const auto& L = lattice.layout();
  const auto n = static_cast<std::size_t>(L.sites);
  const auto& p = lattice.params();
  const double* u = L.primary(s);
  const double* v = L.secondary(s);
  const double* du = L.primary_rate(s);
  const double* dv = L.secondary_rate(s);
  lattice.bond_strains(u, t, r.data());
  bond_energies_from_strains(lattice.law(), r.first(n + 1), r);  // V(r_j)
  for (std::size_t i = 0; i < n; ++i) {
    const double w = u[i] - v[i];
    e[i] = 0.5 * du[i] * du[i] + 0.5 * p.rho * dv[i] * dv[i] + 0.5 * p.kappa * w * w +
           0.5 * (r[i] + r[i + 1]);
  }
}

double energy_centre(std::span<const double> e, Index m) {
  const Index sites = static_cast<Index>(e.size());
  const Index peak = std::max_element(e.begin(), e.end()) - e.begin();
  const Index lo = std::max<Index>(peak - m, 0);
  const Index hi = std::min(sites - 1, peak + m);
  double num = 0, den = 0;
  for (Index i = lo; i <= hi; ++i) {
    num += static_cast<double>(i) * e[static_cast<std::size_t>(i)];
    den += e[static_cast<std::size_t>(i)];
  }
  return den != 0 ? num / den : static_cast<double>(peak);
}

}  // namespace lrchain::sim

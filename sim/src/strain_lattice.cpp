// Strain form of the resonant chain (eq:Hertzd0S) with zero-strain or periodic ends.
#include "lrchain/sim/strain_lattice.hpp"

#include <cstring>

#include "lrchain/errors.hpp"

namespace lrchain::sim {

StrainLattice::StrainLattice(const Params& p, std::size_t sites, StrainEnds ends)
    : params_(p), law_(make_contact_law(p)), layout_{sites}, ends_(ends) {
  if (sites < 2) throw InvalidParameter("sites", "the strain lattice needs at least 2 sites");
  force_.assign(sites + 2, 0.0);
}

// x_n'' and y_n'' of eq:Hertzd0S from F_n = V'(x_n) (F at the ghost sites: 0 or periodic copy).
void StrainLattice::acceleration(const double* q, double* a) const {
  const std::size_t n = layout_.sites;
  const double* x = q;
  const double* y = q + n;
  double* F = force_.data();
  bond_forces_from_strains(law_, x, F + 1, n);
  if (ends_ == StrainEnds::periodic) {
    F[0] = F[n];
    F[n + 1] = F[1];
  } else {
    F[0] = F[n + 1] = 0.0;  // V'(0) = 0 at x_{-N-1} = x_{N+1} = 0
  }
  const double kappa = params_.kappa, kappa_over_rho = params_.kappa / params_.rho;
  double* __restrict ax = a;
  double* __restrict ay = a + n;
  for (std::size_t i = 0; i < n; ++i) {
    const double w = x[i] - y[i];
    ax[i] = F[i + 2] - 2.0 * F[i + 1] + F[i] - kappa * w;
    ay[i] = kappa_over_rho * w;
  }
}

void StrainLattice::operator()(const State& s, State& ds, double /*t*/) const {
  const std::size_t n = layout_.sites;
  std::memcpy(ds.data(), s.data() + 2 * n, 2 * n * sizeof(double));
  acceleration(s.data(), ds.data() + 2 * n);
}

}  // namespace lrchain::sim

// Strain form of the resonant chain (eq:Hertzd0S) with zero-strain or periodic ends.
#include "lrchain/sim/strain_lattice.hpp"

#include <algorithm>
#include <cstring>

#include "lrchain/errors.hpp"
#include "vector_loops.hpp"

namespace lrchain::sim {

namespace {

// x_n'' = F_{n+1} - 2 F_n + F_{n-1} - kappa (x_n - y_n), y_n'' = (kappa/rho)(x_n - y_n)
// (eq:Hertzd0S), F[i] = V'(x) at site i - 1 (one ghost entry on each side).
LRCHAIN_VECTOR_CLONES
void site_accelerations(const double* __restrict F, const double* __restrict x,
                        const double* __restrict y, double* __restrict ax, double* __restrict ay,
                        double kappa, double kappa_over_rho, std::size_t n) {
  for (std::size_t i = 0; i < n; ++i) {
    const double w = x[i] - y[i];
    ax[i] = F[i + 2] - 2.0 * F[i + 1] + F[i] - kappa * w;
    ay[i] = kappa_over_rho * w;
  }
}

}  // namespace

StrainLattice::StrainLattice(const Params& p, Index sites, StrainEnds ends)
    : params_(p), law_(make_contact_law(p)), layout_{std::max<Index>(sites, 0)}, ends_(ends) {
  if (sites < 2) throw InvalidParameter("sites", "the strain lattice needs at least 2 sites");
  force_.assign(layout_.sites + 2, 0.0);
}

// x_n'' and y_n'' of eq:Hertzd0S from F_n = V'(x_n) (F at the ghost sites: 0 or periodic copy).
void StrainLattice::acceleration(const double* q, double* a) const {
  const auto n = static_cast<std::size_t>(layout_.sites);
  const double* x = q;
  const double* y = q + n;
  double* F = force_.data();
  bond_forces_from_strains(law_, {x, n}, {F + 1, n});
  if (ends_ == StrainEnds::periodic) {
    F[0] = F[n];
    F[n + 1] = F[1];
  } else {
    F[0] = F[n + 1] = 0.0;  // V'(0) = 0 at x_{-N-1} = x_{N+1} = 0
  }
  site_accelerations(F, x, y, a, a + n, params_.kappa, params_.kappa / params_.rho, n);
}

void StrainLattice::operator()(const State& s, State& ds, double /*t*/) const {
  const auto n = static_cast<std::size_t>(layout_.sites);
  std::memcpy(ds.data(), s.data() + 2 * n, 2 * n * sizeof(double));
  acceleration(s.data(), ds.data() + 2 * n);
}

}  // namespace lrchain::sim

#include "lrchain/sim/dark/strain_variational.hpp"

#include <cmath>

#include "lrchain/errors.hpp"

namespace lrchain::sim::dark {

StrainLatticeOrbit::StrainLatticeOrbit(const Params& p, Index sites) : p_(p), sites_(sites) {
  validate(p);
  if (sites < 3) throw InvalidParameter("sites", "must be >= 3 (periodic strain lattice)");
  three_halves_ = p.alpha == 1.5;
  kappa_over_rho_ = p.kappa / p.rho;
  force_.assign(static_cast<std::size_t>(sites), 0.0);
}

double StrainLatticeOrbit::force_shifted(double r) const {
  const double s = p_.delta0 - r;
  if (s <= 0.0) return 0.0;
  return three_halves_ ? -s * std::sqrt(s) : -std::pow(s, p_.alpha);
}

double StrainLatticeOrbit::stiffness(double r) const {
  const double s = p_.delta0 - r;
  if (s <= 0.0) return 0.0;
  return three_halves_ ? 1.5 * std::sqrt(s) : p_.alpha * std::pow(s, p_.alpha - 1.0);
}

// eq:Hertzd0S: xdd_n = V'(x_{n+1}) - 2V'(x_n) + V'(x_{n-1}) - kappa (x_n - y_n),
//              rho ydd_n = kappa (x_n - y_n), periodic in n.
void StrainLatticeOrbit::rhs(const double* s, double* ds, double* stiffness_out) const {
  const Index N = sites_;
  const double d0 = p_.delta0;
  double* f = force_.data();
  if (three_halves_) {
    for (Index n = 0; n < N; ++n) {
      const double r = d0 - s[n];
      const double root = r > 0.0 ? std::sqrt(r) : 0.0;
      f[n] = -r * root;
      if (stiffness_out) stiffness_out[n] = 1.5 * root;
    }
  } else {
    for (Index n = 0; n < N; ++n) {
      const double r = d0 - s[n];
      f[n] = r > 0.0 ? -std::pow(r, p_.alpha) : 0.0;
      if (stiffness_out) stiffness_out[n] = r > 0.0 ? p_.alpha * std::pow(r, p_.alpha - 1.0) : 0.0;
    }
  }
  const double* x = s;
  const double* y = s + N;
  const double kappa = p_.kappa;
  for (Index n = 0; n < N; ++n) {
    ds[n] = s[2 * N + n];
    ds[N + n] = s[3 * N + n];
  }
  for (Index n = 0; n < N; ++n) {
    const double fp = f[n + 1 < N ? n + 1 : 0];
    const double fm = f[n > 0 ? n - 1 : N - 1];
    const double diff = x[n] - y[n];
    ds[2 * N + n] = fp - 2.0 * f[n] + fm - kappa * diff;
    ds[3 * N + n] = kappa_over_rho_ * diff;
  }
}

void tangent_block_rhs(Index N, Index B, double kappa, double kappa_over_rho, const double* g,
                       const double* s, double* ds) {
  const double* dx = s;
  const double* dy = s + N * B;
  // d(dx)/dt, d(dy)/dt: copy the velocity rows.
  for (Index i = 0; i < 2 * N * B; ++i) ds[i] = s[2 * N * B + i];
  double* ax = ds + 2 * N * B;
  double* ay = ds + 3 * N * B;
  for (Index n = 0; n < N; ++n) {
    const Index np = n + 1 < N ? n + 1 : 0;
    const Index nm = n > 0 ? n - 1 : N - 1;
    const double gp = g[np], g0 = -2.0 * g[n], gm = g[nm];
    const double* xp = dx + np * B;
    const double* x0 = dx + n * B;
    const double* xm = dx + nm * B;
    const double* y0 = dy + n * B;
    double* axn = ax + n * B;
    double* ayn = ay + n * B;
#pragma omp simd
    for (Index j = 0; j < B; ++j) {
      const double diff = x0[j] - y0[j];
      axn[j] = gp * xp[j] + g0 * x0[j] + gm * xm[j] - kappa * diff;
      ayn[j] = kappa_over_rho * diff;
    }
  }
}

}  // namespace lrchain::sim::dark

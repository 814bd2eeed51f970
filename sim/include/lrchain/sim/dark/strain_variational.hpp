#pragma once
// Strain lattice (eq:Hertzd0S) with periodic ends and its variational equations, for shooting
// Newton and Floquet analysis of dark breathers (Sec. 5.3-5.4).
//
// Orbit state (contiguous): [x(N) y(N) xdot(N) ydot(N)]. The variational equations are linear in
// the tangent vectors with coefficients V''(x_n(t)); they are integrated by replaying the orbit's
// Runge-Kutta steps with the recorded stage stiffnesses (tangent_propagation.hpp), in blocks of
// columns laid out row-major [4N][b] so that the inner loops run over columns (SIMD, in cache).
// Allocation-free; alpha = 3/2 evaluated as s*sqrt(s).
#include <cstddef>
#include <vector>

#include "lrchain/index.hpp"
#include "lrchain/params.hpp"

namespace lrchain::sim::dark {

// Not thread-safe: rhs() writes a scratch buffer of the object; give each thread its own orbit.
class StrainLatticeOrbit {
 public:
  // Throws InvalidParameter for invalid params or sites < 3.
  StrainLatticeOrbit(const Params& p, Index sites);

  Index sites() const { return sites_; }
  Index orbit_size() const { return 4 * sites_; }
  const Params& params() const { return p_; }

  // ds = d/dt s (eq:Hertzd0S, periodic ends). If stiffness_out != nullptr it also receives
  // V''(x_n) for n < N (the coefficients of the variational equations at this state).
  void rhs(const double* s, double* ds, double* stiffness_out = nullptr) const;

  // V'(r) - delta0^alpha = -(delta0 - r)_+^alpha and V''(r) = alpha (delta0 - r)_+^(alpha-1) (eq:Vr).
  double force_shifted(double r) const;
  double stiffness(double r) const;

 private:
  Params p_;
  Index sites_;
  bool three_halves_;
  double kappa_over_rho_;
  mutable std::vector<double> force_;
};

// Variational equations for a block of b tangent vectors, row-major [4N][b]:
// d(dx)/dt = dxdot, d(dxdot)/dt = Lap(g dx) - kappa (dx - dy), rho d(dydot)/dt = kappa (dx - dy),
// with g = V''(x(t)) given per site. No allocation.
void tangent_block_rhs(Index sites, Index block, double kappa, double kappa_over_rho, const double* g,
                       const double* s, double* ds);

}  // namespace lrchain::sim::dark

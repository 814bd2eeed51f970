// Displacement form of the resonant chain (eq:Hertz) with periodic/free/clamped/prescribed ends.
#include "lrchain/sim/displacement_lattice.hpp"

#include <algorithm>
#include <cstring>

#include "lrchain/errors.hpp"
#include "vector_loops.hpp"

namespace lrchain::sim {

namespace {

// u_n'' = f_{n+1} - f_n - kappa (u_n - v_n), v_n'' = (kappa/rho) (u_n - v_n) (eq:Hertz), f the bond
// forces (f_n left of bead n).
LRCHAIN_VECTOR_CLONES
void bead_accelerations(const double* __restrict f, const double* __restrict u,
                        const double* __restrict v, double* __restrict au, double* __restrict av,
                        double kappa, double kappa_over_rho, std::size_t n) {
  for (std::size_t i = 0; i < n; ++i) {
    const double w = u[i] - v[i];
    au[i] = f[i + 1] - f[i] - kappa * w;
    av[i] = kappa_over_rho * w;
  }
}

}  // namespace

DisplacementLattice::DisplacementLattice(const Params& p, Index sites, DisplacementBoundary boundary)
    : params_(p), law_(make_contact_law(p)), layout_{std::max<Index>(sites, 0)},
      boundary_(std::move(boundary)) {
  if (sites < 2) throw InvalidParameter("sites", "the chain needs at least 2 beads");
  for (const EndCondition* e : {&boundary_.left, &boundary_.right})
    if (!boundary_.periodic && e->kind == EndKind::prescribed && !e->motion)
      throw InvalidParameter("boundary", "a prescribed end needs a motion u(t)");
  bond_force_.assign(layout_.sites + 1, 0.0);
  block_force_.assign(block_ + 1, 0.0);
}

bool DisplacementLattice::autonomous() const {
  return boundary_.periodic || (boundary_.left.kind != EndKind::prescribed &&
                                boundary_.right.kind != EndKind::prescribed);
}

double DisplacementLattice::ghost(const EndCondition& e, double t) const {
  return e.kind == EndKind::prescribed ? e.motion(t) : 0.0;
}

// Bond forces f_j = V'(u_j - u_{j-1}), j = 0..sites, with the ghost beads of the boundary.
void DisplacementLattice::acceleration(const double* q, double* a, double t) const {
  const auto n = static_cast<std::size_t>(layout_.sites);
  const double* u = q;
  const double* v = q + n;
  double f_first, f_last;  // bonds 0 and n
  if (boundary_.periodic) {
    f_first = f_last = bond_force(law_, u[0] - u[n - 1]);
  } else {
    f_first = boundary_.left.kind == EndKind::free
                  ? 0.0
                  : bond_force(law_, u[0] - ghost(boundary_.left, t));
    f_last = boundary_.right.kind == EndKind::free
                 ? 0.0
                 : bond_force(law_, ghost(boundary_.right, t) - u[n - 1]);
  }
  // Blocks of beads, so that each block's forces are still in L1 when its accelerations use them;
  // they live in a block-sized scratch (not a whole-chain array), which keeps the stepper's
  // position, momentum and force arrays in L1 too. Block [b0, b1) needs bonds b0..b1, f[k] holds
  // bond b0 + k: bond b0 comes from the previous block (or the left end), interior bonds
  // b0+1..min(b1, n-1) are new, bond n is the right end.
  const double kappa = params_.kappa, kappa_over_rho = params_.kappa / params_.rho;
  double* f = block_force_.data();
  f[0] = f_first;
  for (std::size_t b0 = 0; b0 < n; b0 += block_) {
    const std::size_t b1 = std::min(n, b0 + block_);
    if (b0 > 0) f[0] = f[block_];  // bond b0, the last bond of the previous (full) block
    const std::size_t j0 = b0 + 1, j1 = std::min(b1, n - 1);  // new bonds j0..j1
    if (j1 >= j0) bond_forces_from_displacements(law_, {u + j0 - 1, j1 - j0 + 2}, {f + 1, j1 - j0 + 1});
    if (b1 == n) f[n - b0] = f_last;
    bead_accelerations(f, u + b0, v + b0, a + b0, a + n + b0, kappa, kappa_over_rho, b1 - b0);
  }
}

void DisplacementLattice::operator()(const State& s, State& ds, double t) const {
  const auto n = static_cast<std::size_t>(layout_.sites);
  std::memcpy(ds.data(), s.data() + 2 * n, 2 * n * sizeof(double));
  acceleration(s.data(), ds.data() + 2 * n, t);
}

void DisplacementLattice::bond_strains(const double* u, double t, double* r) const {
  const auto n = static_cast<std::size_t>(layout_.sites);
  for (std::size_t j = 1; j < n; ++j) r[j] = u[j] - u[j - 1];
  if (boundary_.periodic) {
    r[0] = r[n] = u[0] - u[n - 1];
  } else {
    r[0] = boundary_.left.kind == EndKind::free ? 0.0 : u[0] - ghost(boundary_.left, t);
    r[n] = boundary_.right.kind == EndKind::free ? 0.0 : ghost(boundary_.right, t) - u[n - 1];
  }
}

double DisplacementLattice::total_energy(const State& s, double t) const {
  const auto n = static_cast<std::size_t>(layout_.sites);
  const double* u = layout_.primary(s);
  const double* v = layout_.secondary(s);
  const double* du = layout_.primary_rate(s);
  const double* dv = layout_.secondary_rate(s);
  double e = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double w = u[i] - v[i];
    e += 0.5 * du[i] * du[i] + 0.5 * params_.rho * dv[i] * dv[i] + 0.5 * params_.kappa * w * w;
  }
  double* V = bond_force_.data();  // scratch: bond strains, then V(r_j) (eq:Vr)
  bond_strains(u, t, V);
  bond_energies_from_strains(law_, {V, n + 1}, {V, n + 1});
  for (std::size_t j = 1; j < n; ++j) e += V[j];
  if (boundary_.periodic) {
    e += V[0];
  } else {
    if (boundary_.left.kind != EndKind::free) e += V[0];
    if (boundary_.right.kind != EndKind::free) e += V[n];
  }
  return e;
}

}  // namespace lrchain::sim

#pragma once
// The resonant granular chain in displacement form (eq:Hertz):
//   u_n'' = V'(u_{n+1}-u_n) - V'(u_n-u_{n-1}) - kappa (u_n - v_n),  rho v_n'' = kappa (u_n - v_n),
// on beads 0..sites-1 with periodic ends, or with each end free, clamped (ghost bead at rest), or
// moved (ghost bead displacement prescribed as a function of time, e.g. u_0(t) of Sec. 4.3).
// The RHS works on contiguous arrays and allocates nothing.
#include <cstddef>
#include <functional>
#include <vector>

#include "lrchain/index.hpp"
#include "lrchain/params.hpp"
#include "lrchain/sim/contact_law.hpp"
#include "lrchain/sim/state.hpp"

namespace lrchain::sim {

enum class EndKind {
  free,        // no neighbour: no contact force (equivalent to zero strain at the ghost site)
  clamped,     // ghost bead fixed at u = 0
  prescribed,  // ghost bead displacement given by `motion(t)`
};

struct EndCondition {
  EndKind kind = EndKind::free;
  std::function<double(double)> motion;  // ghost displacement u(t) when kind == prescribed
};

struct DisplacementBoundary {
  bool periodic = false;  // u_{n+sites} = u_n (eq:cimi runs); then left/right are ignored
  EndCondition left;      // ghost bead before bead 0
  EndCondition right;     // ghost bead after bead sites-1
};

// Not thread-safe: acceleration() and total_energy() are const but write scratch buffers of the
// object (no allocation per call); give each thread its own lattice.
class DisplacementLattice {
 public:
  // Throws InvalidParameter("sites", ...) for fewer than 2 beads.
  DisplacementLattice(const Params& p, Index sites, DisplacementBoundary boundary = {});

  Index sites() const { return layout_.sites; }
  const StateLayout& layout() const { return layout_; }
  const Params& params() const { return params_; }
  const ContactLaw& law() const { return law_; }
  const DisplacementBoundary& boundary() const { return boundary_; }
  bool autonomous() const;  // no prescribed end motion

  // First-order system for Odeint: state [u v u' v'] -> derivative (eq:Hertz).
  void operator()(const State& s, State& ds, double t) const;
  // Accelerations only (for Runge-Kutta-Nystroem steppers): q = [u v], a = [u'' v''].
  void acceleration(const double* q, double* a, double t) const;

  // Bond strains r_j = u_j - u_{j-1} for j = 0..sites (bond j is left of bead j), ghost beads
  // from the boundary condition. For free ends the missing bonds are reported as 0.
  void bond_strains(const double* u, double t, double* r) const;
  // Total energy: kinetic + resonator springs + all contact bonds (eq:Vr); conserved for
  // autonomous boundaries.
  double total_energy(const State& s, double t = 0) const;

 private:
  double ghost(const EndCondition& e, double t) const;

  Params params_;
  ContactLaw law_;
  StateLayout layout_;
  DisplacementBoundary boundary_;
  mutable std::vector<double> bond_force_;   // scratch of total_energy, sites + 1 entries
  static constexpr std::size_t block_ = 256;  // beads per block of acceleration()
  mutable std::vector<double> block_force_;  // scratch of acceleration: one block's bond forces
};

}  // namespace lrchain::sim

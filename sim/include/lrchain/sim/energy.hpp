#pragma once
// Energy diagnostics of the displacement form: energy density e_n (eq:edensity, any alpha) and the
// local energy centre X (eq:ectr).
#include <span>

#include "lrchain/index.hpp"
#include "lrchain/sim/displacement_lattice.hpp"

namespace lrchain::sim {

// e_n = u'^2/2 + rho v'^2/2 + kappa (u-v)^2/2 + [V(u_n-u_{n-1}) + V(u_{n+1}-u_n)]/2 (eq:edensity,
// written with eq:Vr so that it holds for any alpha). Missing bonds at free ends count as V(0)=0.
// `e` has sites entries; `bond_scratch` sites+1 entries. No allocation.
void energy_density(const DisplacementLattice& lattice, const State& s, double t, std::span<double> e,
                    std::span<double> bond_scratch);

// Energy centre X = sum i e_i / sum e_i over i in [n'-m, n'+m] (clipped to the chain), n' the site
// of maximal e (eq:ectr). Returned as a bead index (0-based); adding the label of bead 0 gives the
// paper's labels (e.g. -N-1 for the bright runs).
double energy_centre(std::span<const double> e, Index m);

}  // namespace lrchain::sim

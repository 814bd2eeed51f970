#pragma once
// Whether a converged Z(0) of a model's shooting is a dark breather and not another periodic orbit
// Newton found (a standing wave, an irregular state): far from the dip(s) the background is the edge's
// plane wave, the seed's far-field pattern P (tanh -> +-1, so the phase flips across each dip) with
// one amplitude B about a mean shift m_f per field (even nonlinearities make the turning points
// asymmetric), B within a factor of the NLS amplitude A at omega_b, and next to every dip centre the
// carrier has fallen below B.
#include <string>

#include <Eigen/Dense>

#include "lrchain/ansatz/dark_breather.hpp"
#include "lrchain/index.hpp"
#include "lrchain/sim/dark/dark_ansatz.hpp"

namespace lrchain::sim::dark {

// What a dark breather's profile must show, as fractions of its far-field amplitude B.
struct DarkShapeTolerances {
  double background_spread = 0.1;  // far values within background_spread B |P| of m_f +- B |P| (P: the plane wave's pattern)
  double amplitude_factor = 3.0;   // B within [A/factor, A factor] of the NLS amplitude A at omega_b
  // The carrier's smallest |z - m_f| within 1.5 sites of a dip centre <= dip_depth B |P|. Loose on
  // purpose: a narrow bond-centred dark breather is mostly its phase flip (its central pair at 81% of
  // B for klein_gordon b = -1/2 at omega_b = 0.9; all of B in the anti-continuum limit), and the
  // flip is already required of the far field by P's sign on either side.
  double dip_depth = 0.95;
};

// Empty when z (Z(0) on `sites`, field-major, in the lattice's variables, as dark_seed lays it out)
// is a dark breather of the ansatz's edge; otherwise the reason, e.g. "the far field is not the plane
// wave of the edge: its amplitude varies by 87% over the 8 sites farthest from the dip".
std::string dark_shape_failure(const DarkAnsatz& ansatz, DarkCenter center, Index sites, const Eigen::VectorXd& z,
                               const DarkShapeTolerances& tolerances = {});

}  // namespace lrchain::sim::dark

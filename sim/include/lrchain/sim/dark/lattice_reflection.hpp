#pragma once
// The reflection symmetry of a dark breather of a model lattice (issue 27, continuation): an index
// reflection of the periodic ring, field by field i -> (K_f - i) mod N with a sign s_f, that maps the
// lattice equations to themselves (checked on the generated accelerations) and the breather to itself,
// either at every time (Z(t) = R Z(t)) or after half a period (Z(t + T_b/2) = R Z(t)). Imposing it
// removes the breather's translation (pinning) mode from the shooting problem, as the resonant chain's
// site/bond families do (resonant_chain_shooting.hpp).
#include <Eigen/Dense>
#include <optional>
#include <string>
#include <vector>

#include "lrchain/index.hpp"
#include "lrchain/sim/model_lattice.hpp"

namespace lrchain::sim::dark {

struct LatticeReflection {
  std::vector<Index> image;  // position p (field-major, f * sites + i) -> its image
  std::vector<double> sign;  // (R z)[image[p]] = sign[p] z[p]
  bool half_period = false;  // Z(t + T_b/2) = R Z(t); false: Z(t) = R Z(t)
  std::string description;   // e.g. "i -> (61 - i) mod 61 with sign (+), after half a period"
};

// R z.
Eigen::VectorXd reflect(const LatticeReflection& reflection, const Eigen::VectorXd& z);

// Orthonormal bases (columns) of the R-even (R v = v) and R-odd (R v = -v) subspaces.
Eigen::MatrixXd reflection_even_basis(const LatticeReflection& reflection);
Eigen::MatrixXd reflection_odd_basis(const LatticeReflection& reflection);

// The reflection about the array position `centre` (site index, a half-integer between two sites)
// under which the seed is symmetric: R seed = seed (at all times) or R seed = seed_half_period (the
// seed half a period later), each field's index map i -> (2 centre + o - i) mod N with o in {0, 1} (a
// strain lives on a bond) and sign +-1, that also commutes with the lattice's accelerations at two
// random states around the seed (relative 1e-10). The seed must be symmetric to `tolerance` relative
// to its largest entry (the seed formulas are to round-off; a solved breather only to its weakly
// pinned translation direction). nullopt when no such reflection exists (a lattice without
// reflection symmetry).
std::optional<LatticeReflection> find_dark_reflection(const CompiledLattice& lattice, double centre,
                                                      const Eigen::VectorXd& seed,
                                                      const Eigen::VectorXd& seed_half_period,
                                                      double tolerance = 1e-6);

}  // namespace lrchain::sim::dark

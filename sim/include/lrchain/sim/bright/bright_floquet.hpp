#pragma once
// Floquet stability of an exact bright breather from its full-period monodromy matrix M (the
// variational equations integrated over T_b, shooting.hpp). A Hamiltonian lattice has the trivial
// multiplier +1 twice (the phase mode: time translation, and its partner: the change of frequency
// along the family; Aubry, Physica D 103, 201 (1997), Sec. 3), and a translation-invariant lattice
// in strain form twice more (the conserved total strain and its partner). Those are identified (the
// ones nearest +1), reported and removed; the breather is stable iff every remaining |lambda| <= 1 + tol.
// The symplectic structure gives (lambda, 1/conj(lambda)) pairs and det M = 1: the pairing defect and
// |det M - 1| measure how well the integration kept it.
#include <complex>
#include <vector>

#include <Eigen/Dense>

#include "lrchain/index.hpp"
#include "lrchain/sim/dark/floquet.hpp"

namespace lrchain::sim::bright {

struct BrightFloquetOptions {
  double unit_tolerance = 1e-6;     // |lambda| > 1 + tol counts as unstable
  double trivial_tolerance = 1e-3;  // the trivial multipliers must lie this close to +1
};

struct BrightFloquet {
  dark::FloquetResult multipliers;             // all multipliers (|lambda| descending), classified without the trivial ones
  std::vector<std::complex<double>> trivial;   // the multipliers identified as the trivial +1 ones
  Index trivial_expected = 2;                  // 2 (phase), 4 with a mean flow (strain form)
  bool trivial_found = false;                  // all trivial_expected lie within trivial_tolerance of +1
  double trivial_distance = 0;                 // max |lambda - 1| over `trivial`
  double max_nontrivial_modulus = 0;           // max |lambda| over the others
  double unit_circle_defect = 0;               // max ||lambda| - 1| over the others
  double det_defect = 0;                       // |det M - 1|
  bool stable = false;                         // trivial_found and max_nontrivial_modulus <= 1 + unit_tolerance
};

// The multipliers of `monodromy` (Eigen's EigenSolver), the trivial ones removed.
BrightFloquet bright_floquet(const Eigen::MatrixXd& monodromy, bool mean_flow, const BrightFloquetOptions& options = {});

}  // namespace lrchain::sim::bright

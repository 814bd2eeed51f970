#pragma once
// Bifurcations along a continued bright-breather branch, from its points in order: folds (d omega_b/ds
// changes sign; located on the cubic Hermite interpolant of omega_b(s) through the two points that
// bracket it), branch points (the number of real nontrivial multipliers beyond +1 changes: a pair
// collides at +1 and leaves along the real axis), period doublings (the number beyond -1 changes) and
// Krein collisions (an oscillatory instability sets in: a complex quadruplet off the unit circle, which
// only two multipliers of opposite Krein signature can form, krein_signature.hpp).
// A multiplier crossing is bracketed by two points, not located: omega_b of its record is the middle
// of the bracket, and omega_low/omega_high the bracket itself.
#include <optional>
#include <string>
#include <vector>

#include "lrchain/index.hpp"
#include "lrchain/sim/bright/bright_floquet.hpp"

namespace lrchain::sim::bright {

// One branch point as the detector sees it.
struct BranchSample {
  double arclength = 0;       // s: cumulative pseudo-arclength in (Z(0), omega_b) from the first point
  double omega_b = 0;
  double tangent_omega = 0;   // d omega_b / ds
  double norm_squared = 0;    // sum of Z(0)^2 (BrightProfile::norm_squared)
  std::optional<Index> real_unstable;       // nontrivial real multipliers > 1 + tol (nullopt: no Floquet here)
  std::optional<Index> period_doubling;     // nontrivial real multipliers < -1 - tol
  std::optional<bool> oscillatory;          // a nontrivial non-real multiplier off the unit circle
};

struct BranchBifurcation {
  std::string kind;          // fold | branch_point | period_doubling | krein_collision
  Index index = 0;           // between branch points index and index + 1
  double omega_b = 0;        // fold: located; crossing: the middle of [omega_low, omega_high]
  double norm_squared = 0;   // interpolated at omega_b (linear in s, or in omega_b for a crossing)
  double omega_low = 0, omega_high = 0;  // the bracketing points' omega_b (ordered)
};

// The nontrivial real multipliers beyond +1 (sign = +1) or beyond -1 (sign = -1) by more than `tolerance`
// (|Im lambda| <= FloquetOptions::real_tolerance |lambda|, as classify_multipliers), the trivial ones of `f` left out.
Index real_multipliers_beyond(const BrightFloquet& f, int sign, double tolerance);

// The folds and multiplier crossings between consecutive samples, in branch order.
std::vector<BranchBifurcation> branch_bifurcations(const std::vector<BranchSample>& samples);

}  // namespace lrchain::sim::bright

#pragma once
// Bifurcations along a continued bright-breather branch, from its points in order: folds (d omega_b/ds
// changes sign; located on the cubic Hermite interpolant of omega_b(s) through the two points that
// bracket it), branch points (the number of real nontrivial multipliers beyond +1 changes: a pair
// collides at +1 and leaves along the real axis), period doublings (the number beyond -1 changes), period
// triplings (the number in the sector |arg lambda| > 2 pi/3 changes: a multiplier passes exp(+-2 pi i/3),
// where the breather's third iterate has a multiplier +1) and Krein collisions (an oscillatory instability
// sets in: a complex quadruplet off the unit circle, which only two multipliers of opposite Krein
// signature can form, krein_signature.hpp).
// A multiplier crossing is first bracketed by two points (omega_b the middle of the bracket,
// omega_low/omega_high the bracket itself: along a model parameter, that parameter's values);
// locate_crossing() then narrows it by bisection on re-solved breathers between them.
#include <complex>
#include <functional>
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
  std::optional<Index> period_tripling;     // nontrivial multipliers with |arg lambda| > 2 pi/3
};

struct BranchBifurcation {
  std::string kind;          // fold | branch_point | period_doubling | period_tripling | krein_collision
  Index index = 0;           // between branch points index and index + 1
  double omega_b = 0;        // fold: located; crossing: the middle of [omega_low, omega_high] or, located, of the final bracket
  double norm_squared = 0;   // interpolated at omega_b (linear in s, or in omega_b for a crossing); located: at the final bracket's far end
  double omega_low = 0, omega_high = 0;  // the bracketing points' omega_b (ordered)
  // a crossing located by locate_crossing: half the final bracket's width (|omega_b - crossing| <= this)
  // and the crossing multiplier at the final bracket's far end (branch order)
  bool located = false;
  double location_error = 0;
  std::optional<std::complex<double>> multiplier;
};

// The nontrivial real multipliers beyond +1 (sign = +1) or beyond -1 (sign = -1) by more than `tolerance`
// (|Im lambda| <= FloquetOptions::real_tolerance |lambda|, as classify_multipliers), the trivial ones of `f` left out.
Index real_multipliers_beyond(const BrightFloquet& f, int sign, double tolerance);

// The nontrivial multipliers of `f` in the sector |arg lambda| > 2 pi/3 (period tripling's indicator).
Index multipliers_beyond_two_thirds(const BrightFloquet& f);

// The folds and multiplier crossings between consecutive samples, in branch order.
std::vector<BranchBifurcation> branch_bifurcations(const std::vector<BranchSample>& samples);

// The integer a crossing of `kind` changes (branch_point: real multipliers beyond +1; period_doubling:
// beyond -1; period_tripling: in |arg lambda| > 2 pi/3; krein_collision: 1 if oscillatory, else 0).
Index crossing_indicator(const std::string& kind, const BrightFloquet& f, double unit_tolerance);

// The multiplier that makes a crossing of `kind`: the nontrivial one nearest +1, -1 or exp(2 pi i/3)
// (upper half plane), or (krein_collision) the non-real one of largest modulus in the upper half plane; of a pair
// (lambda, 1/conj(lambda)) off the unit circle, the one outside.
std::complex<double> crossing_multiplier(const std::string& kind, const BrightFloquet& f);

// A breather re-solved at a value of the continued parameter (omega_b, or a model parameter at fixed
// omega_b) from a guess of its Z(0): its Z(0), Floquet analysis and norm, or nullopt when Newton fails
// or the zero is no localized breather.
struct CrossingSolution {
  Eigen::VectorXd z0;
  BrightFloquet floquet;
  double norm_squared = 0;
};
using CrossingSolver = std::function<std::optional<CrossingSolution>(double value, const Eigen::VectorXd& guess)>;

// Locates crossing `b` (not a fold) between its bracketing points, at (p_a, z_a) and (p_b, z_b) in branch
// order (p the continued parameter) with Floquet analyses fa and fb, by bisection in p on crossing_indicator: each
// midpoint re-solved by `solve` from Z(0) interpolated linearly between the bracket's ends, until the
// bracket is at most `tolerance` wide. Sets b.omega_b (the final bracket's middle), b.location_error,
// b.multiplier, b.norm_squared and b.located; leaves b as it is when a re-solve fails.
void locate_crossing(BranchBifurcation& b, double p_a, const Eigen::VectorXd& z_a, const BrightFloquet& fa,
                     double p_b, const Eigen::VectorXd& z_b, const BrightFloquet& fb, const CrossingSolver& solve,
                     double unit_tolerance, double tolerance);

}  // namespace lrchain::sim::bright

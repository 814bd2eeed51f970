#pragma once
// What a converged shooting solution Z(0) is: a localized bright breather (it decays to zero far from
// the centre and has one maximum, at the centre) or not (a Newton zero that is a wave filling the ring,
// a breather centred elsewhere, or several humps), and its measures beside the NLS seed's.
#include <string>

#include <Eigen/Dense>

#include "lrchain/index.hpp"

namespace lrchain::sim::bright {

struct BrightProfileOptions {
  double tail_tolerance = 1e-3;   // max |Z| on the ring's far quarter <= this x the peak: decayed
  double shape_tolerance = 1e-6;  // the envelope may rise outward by at most this x the peak
  // Where the breather's centre lies on x_0's sites, from the middle site: the envelope's n0 (bond: 1/2),
  // plus 1/2 in strain form (r[n] = u[n] - u[n-1] sits between u[n-1] and u[n]). A bond-centred
  // breather of a cell with several fields (centred on the second bead) peaks in r up to two sites on.
  double centre_position = 0;
};

struct BrightProfile {
  double peak = 0;            // max_n |x_0[n]|: the first variable's amplitude at t = 0
  Index peak_site = 0;        // its site index i on the ring (0 .. sites - 1)
  double tail = 0;            // max |Z| over every variable on the ring's far quarter, / peak
  double width = 0;           // participation width (sum_n x_0^2)^2 / sum_n x_0^4 of the first variable (sites)
  double norm_squared = 0;    // sum over every variable and site of Z(0)^2
  bool localized = false;
  std::string reason;         // why not localized ("" when it is)
};

// The profile of Z(0) (field-major, `sites` per variable, centre at the middle site (sites - 1)/2).
// Localized when the tail has decayed (tail <= tail_tolerance), the peak of the first variable sits at
// the centre (within one site of the middle site or of centre_position: a bond-centred breather has two
// equal maxima) and the envelope (the
// maximum of |x_0| over pairs of neighbouring sites, so that a staggered carrier riding on a mean
// offset counts as one hump) does not rise moving outward from the centre by more than
// shape_tolerance x the peak.
BrightProfile inspect_bright_profile(const Eigen::VectorXd& z0, Index sites, const BrightProfileOptions& options = {});

// max over every variable and site of |z - reference| / max |z|: the distance of an exact breather from
// its NLS seed (both Z(0) in the same variables).
double relative_profile_difference(const Eigen::VectorXd& z, const Eigen::VectorXd& reference);

}  // namespace lrchain::sim::bright

#pragma once
// Lattice state storage shared by all lattice systems: one contiguous vector of 4*sites doubles,
// laid out as [q1 (sites) | q2 (sites) | dq1/dt (sites) | dq2/dt (sites)], where (q1, q2) are
// (u, v) in the displacement form (eq:Hertz) and (x, y) in the strain form (eq:Hertzd0S).
#include <vector>

#include "lrchain/index.hpp"

namespace lrchain::sim {

using State = std::vector<double>;

// Views into a State of `sites` sites.
struct StateLayout {
  Index sites = 0;
  Index size() const { return 4 * sites; }
  double* primary(State& s) const { return s.data(); }                   // u or x
  double* secondary(State& s) const { return s.data() + sites; }         // v or y
  double* primary_rate(State& s) const { return s.data() + 2 * sites; }  // du/dt or dx/dt
  double* secondary_rate(State& s) const { return s.data() + 3 * sites; }
  const double* primary(const State& s) const { return s.data(); }
  const double* secondary(const State& s) const { return s.data() + sites; }
  const double* primary_rate(const State& s) const { return s.data() + 2 * sites; }
  const double* secondary_rate(const State& s) const { return s.data() + 3 * sites; }
};

}  // namespace lrchain::sim

#pragma once
// Focusing theta-intervals in (0, pi] (omega'' h_tilde < 0, Sec. 3.3 and eq:NLS) with each end
// labelled by its cause, found by root finding on the underlying smooth functions.
#include <vector>

#include "lrchain/dispersion.hpp"
#include "lrchain/index.hpp"
#include "lrchain/params.hpp"
#include "lrchain/regime/boundary_cause.hpp"
#include "lrchain/regime/regime_functions.hpp"

namespace lrchain::regime {

struct BoundaryRoot {
  double theta = 0;
  BoundaryCause cause = BoundaryCause::band_edge;
};

struct FocusingInterval {
  double lo = 0, hi = 0;
  BoundaryCause lo_cause = BoundaryCause::band_edge, hi_cause = BoundaryCause::band_edge;
};

struct IntervalOptions {
  Index samples = 2048;        // theta samples pi*i/samples, i = 1..samples, for bracketing
  double x_tolerance = 1e-12;  // accuracy of every interval end in theta
};

// The sign structure along (0, pi]: every zero of the four smooth functions (sorted by theta)
// and the focusing intervals they delimit.
struct RegimeStructure {
  std::vector<BoundaryRoot> roots;
  std::vector<FocusingInterval> intervals;
};

RegimeStructure regime_structure(const RegimeFunctions& f, const IntervalOptions& options = {});

// Focusing intervals of the resonant chain for one branch (validates p).
std::vector<FocusingInterval> focusing_intervals(const Params& p, Branch b,
                                                 const IntervalOptions& options = {});

}  // namespace lrchain::regime

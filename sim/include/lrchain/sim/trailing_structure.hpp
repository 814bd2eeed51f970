#pragma once
// A secondary localised structure left behind a moving bright breather (Sec. 4.2, Fig. 11: "a
// small optical breather detaches and moves left at about -c_+"): located in the recorded energy
// density e_n(t) (eq:edensity) as the maximum of e_n behind the parent (n < X(t) - gap, X the
// energy centre eq:ectr), its speed a least-squares fit of the local energy centre over time, and
// its branch read from the final strains: y_n/x_n = kappa/(kappa - rho omega^2) is > 0 on the
// acoustic branch and < 0 on the optical branch (eq:b10b11), so the sign tells which it is.
#include <span>
#include <vector>

#include "lrchain/index.hpp"
#include "lrchain/sim/run_record.hpp"

namespace lrchain::sim {

struct TrailingStructureOptions {
  double fit_start = 0;      // fit the speed over field rows with t >= fit_start (> 0 to enable)
  double gap = 150;          // sites between the parent's energy centre and the searched region
  Index half_window = 40;    // local energy centre and y/x over max site +- half_window
  Index far_end = 800;       // ignore |n| > far_end (fast sound pulses reaching the ends)
};

struct TrailingStructure {
  bool found = false;
  double speed = 0;           // d(local energy centre)/dt over t >= fit_start
  double centre_end = 0;      // its local energy centre at the last field row (paper label)
  double max_energy_density = 0;  // max e_n there at the last row
  double max_abs_x = 0;       // max |x_n| in the window at the final time
  double y_over_x = 0;        // least-squares ratio of (y - mean y) to (x - mean x) in the window
};

// field: e_n rows (first_label = label of its site 0); centre_t/centre_x: X(t) series (paper
// labels); x, y: final strains (of one size) on labels x_first .. x_first + x.size() - 1.
TrailingStructure track_trailing_structure(const SpaceTime& field, const std::vector<double>& centre_t,
                                           const std::vector<double>& centre_x, std::span<const double> x,
                                           std::span<const double> y, Index x_first,
                                           const TrailingStructureOptions& opt);

}  // namespace lrchain::sim

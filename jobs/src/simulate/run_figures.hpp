#pragma once
// gnuplot script pieces the resonant chain's run figures share (bright, drive, modulated): the top
// of the energy-density colour scale, the energy-density panel, the velocity snapshots. Private to jobs/src.
#include <cstddef>
#include <string>

#include "lrchain/sim/run_record.hpp"

namespace lrchain::jobs {

// The largest e_n (eq. (40)) in the run's space-time fields; 1 when none is > 0.
float largest_energy_density(const sim::RunRecord& record);

// The head of energy.png (1400 x `height`, two panels): the left panel's axes and e_n(t) on a
// logarithmic colour scale [low, high]; the caller's plot command follows.
std::string log_energy_panel_head(int height, double low, double high);

// snapshots.png: bead velocities du_n/dt at the `snapshots` snapshot times (`figure`: "Fig. 15"),
// one panel of `row_height` pixels each, plotted by `body`.
std::string velocity_snapshots_script(const std::string& figure, std::size_t row_height, std::size_t snapshots,
                                      const std::string& body);

}  // namespace lrchain::jobs

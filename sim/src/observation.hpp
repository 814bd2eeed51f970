#pragma once
// Pieces shared by the run observers (bright, drive, modulated): the merged list of observation
// times and the displacement-form snapshot (n, u, v, u_dot, v_dot, e_n of eq:edensity).
#include <span>
#include <string>
#include <vector>

#include "lrchain/index.hpp"
#include "lrchain/sim/run_record.hpp"
#include "lrchain/sim/state.hpp"

namespace lrchain::sim {

// `times` and `extra` merged, sorted, with times closer than 1e-9 * scale counted once.
std::vector<double> merge_observation_times(std::vector<double> times,
                                            const std::vector<double>& extra, double scale);

// Snapshot of a displacement-form state (eq:Hertz): columns n, u, v, u_dot, v_dot, e with
// n = first_label + bead index; e holds the energy density of each bead (L.sites entries).
Snapshot displacement_snapshot(const StateLayout& L, const State& s, std::span<const double> e, double t,
                               std::string tag, Index first_label);

}  // namespace lrchain::sim

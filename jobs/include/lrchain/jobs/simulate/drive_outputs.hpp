#pragma once
// Files of the driven chain's run (experiment 6, Sec. 4.3) in --out: series.csv, snapshot_*.csv,
// energy_density_spacetime.bin, summary.json, energy.gp/.png (Fig. 14 left) and snapshots.gp/.png (Fig. 15).
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "lrchain/sim/drive_run.hpp"

namespace lrchain::jobs {

// The JSON summary of a drive run (drive, integrator, front speed, participation, run status).
nlohmann::json to_json(const sim::DriveRunConfig& c, const sim::DriveRunSummary& s);

// Writes data, summary.json and figures; returns the figure files rendered.
std::vector<std::string> write_drive_outputs(const std::string& dir, const sim::DriveRunResult& r,
                                             const nlohmann::json& summary, bool draw_figures = true);

}  // namespace lrchain::jobs

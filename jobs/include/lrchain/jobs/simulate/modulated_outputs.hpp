#pragma once
// Files of the modulated wave's run (experiment 7, Sec. 5.1) in --out: series.csv, snapshot_*.csv,
// energy_density_spacetime.bin, summary.json, energy.gp/.png and snapshots.gp/.png (Fig. 16).
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "lrchain/sim/modulated_run.hpp"

namespace lrchain::jobs {

// The JSON summary of a modulated run (initial wave, contrast, dark-breather speed, run status).
nlohmann::json to_json(const sim::ModulatedRunConfig& c, const sim::ModulatedRunSummary& s);

// Writes data, summary.json and figures; returns the figure files rendered.
std::vector<std::string> write_modulated_outputs(const std::string& dir, const sim::ModulatedRunResult& r,
                                                 const nlohmann::json& summary, bool draw_figures = true);

}  // namespace lrchain::jobs

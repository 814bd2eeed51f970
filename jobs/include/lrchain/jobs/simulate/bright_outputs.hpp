#pragma once
// Files of a bright-breather run in --out: series.csv, snapshot_*.csv, energy_density_spacetime.bin,
// summary.json, and the figures snapshots.gp/.png (like Figs. 6, 8, 10: profiles vs ansatz and
// E_x, E_y) and energy.gp/.png (like Figs. 7, 9: e_n space-time and energy centre X(t)).
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "lrchain/sim/resonant_chain_bright_run.hpp"

namespace lrchain::jobs {

// The JSON summary of a bright run (config, NLS coefficients, errors, energy, centre, run status).
nlohmann::json to_json(const sim::BrightRunConfig& c, const sim::BrightRunSummary& s);

// Writes data, summary.json (= `summary`) and, with draw_figures, the figures; returns the list of
// figure files rendered.
std::vector<std::string> write_bright_outputs(const std::filesystem::path& dir, const sim::BrightRunResult& r,
                                              const nlohmann::json& summary, bool draw_figures = true);

}  // namespace lrchain::jobs

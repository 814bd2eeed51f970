#pragma once
// JSON summary (model, file hash, parameters, per amplitude, packet) and the output directory of a
// ring run (sim/ring_run.hpp): ring_frequency.csv, series.csv, frequency.gp/png, packet.gp/png, summary.json.
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "lrchain/model.hpp"
#include "lrchain/sim/ring_run.hpp"

namespace lrchain::jobs {

nlohmann::json to_json(const Model& model, const sim::RingRunConfig& c, const sim::RingRunResult& r);
std::vector<std::string> write_ring_outputs(const std::filesystem::path& dir, const sim::RingRunResult& r,
                                            const nlohmann::json& summary, bool draw_figures);

}  // namespace lrchain::jobs

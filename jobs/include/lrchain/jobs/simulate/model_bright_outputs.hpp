#pragma once
// JSON summary and files of a model bright-breather run (sim/bright_run.hpp) in --out:
// series.csv, the final snapshot, summary.json and errors.gp/.png.
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "lrchain/model.hpp"
#include "lrchain/sim/bright_run.hpp"

namespace lrchain::jobs {

// The run's checks that did not pass, one sentence each (a breather that reached a fixed end).
std::vector<std::string> model_bright_warnings(const sim::ModelBrightResult& r);
nlohmann::json to_json(const Model& model, const sim::ModelBrightConfig& c, const sim::ModelBrightResult& r);
std::vector<std::string> write_model_bright_outputs(const std::filesystem::path& dir, const sim::ModelBrightResult& r,
                                                    const nlohmann::json& summary, bool draw_figures);

}  // namespace lrchain::jobs

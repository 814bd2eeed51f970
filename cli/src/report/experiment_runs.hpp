#pragma once
// Simulator runs of `lrchain reproduce`: an experiment config from examples/ (optionally edited
// for the quick run) is written into the report's configs/ directory and run with
// `lrchain simulate --config`, so every run in the report can be repeated as it was made.
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>
#include <toml++/toml.h>

#include "steps.hpp"

namespace lrchain::report {

// A CSV file with a header row; non-numeric cells are kept as text.
struct CsvTable {
  std::vector<std::string> names;
  std::vector<std::vector<std::string>> cells;
  std::size_t column(const std::string& name) const;  // throws if absent
  double number(std::size_t row, const std::string& name) const;
};
CsvTable read_csv(const std::filesystem::path& file);  // throws std::runtime_error if unreadable

struct ExperimentRun {
  nlohmann::json summary;             // the run's summary.json
  std::filesystem::path dir;          // its output directory
  std::vector<std::vector<double>> series;  // series.csv rows
  std::vector<std::string> series_names;
  std::size_t column(const std::string& name) const;  // index in series_names (throws if absent)
};

// Copies examples/<config> to configs/<id>.toml (after `edit(config, ctx.full)`, if set), runs it
// into <id>/ and reads summary.json and series.csv.
using ConfigEdit = std::function<void(toml::table&, bool full)>;
ExperimentRun run_experiment(const StepContext& ctx, const std::string& id, const std::string& config,
                             const ConfigEdit& edit, Section& section);

// j[key] if it is a number, else not_computed.
inline double json_number(const nlohmann::json& j, const std::string& key) {
  return j.contains(key) && j[key].is_number() ? j[key].get<double>() : not_computed;
}

// Sets table[key] = value inside the sub-table `table_name` of a config.
void set_config(toml::table& config, const std::string& table_name, const std::string& key,
                toml::node&& value);

}  // namespace lrchain::report

// Experiment runs from examples/*.toml for `lrchain reproduce` (see experiment_runs.hpp).
#include "experiment_runs.hpp"

#include <fstream>
#include <sstream>
#include <stdexcept>

#include "lrchain/jobs/output_files.hpp"
#include "lrchain_process.hpp"

namespace lrchain::report {

namespace fs = std::filesystem;

std::size_t ExperimentRun::column(const std::string& name) const {
  for (std::size_t i = 0; i < series_names.size(); ++i)
    if (series_names[i] == name) return i;
  throw std::runtime_error("series.csv of " + dir.string() + " has no column " + name);
}

void set_config(toml::table& config, const std::string& table_name, const std::string& key,
                toml::node&& value) {
  auto* t = config[table_name].as_table();
  if (!t) throw std::runtime_error("config has no [" + table_name + "] table");
  t->insert_or_assign(key, std::move(value));
}

std::size_t CsvTable::column(const std::string& name) const {
  for (std::size_t i = 0; i < names.size(); ++i)
    if (names[i] == name) return i;
  throw std::runtime_error("CSV has no column " + name);
}

double CsvTable::number(std::size_t row, const std::string& name) const {
  return std::strtod(cells.at(row).at(column(name)).c_str(), nullptr);
}

CsvTable read_csv(const fs::path& file) {
  std::ifstream in(file);
  if (!in) throw std::runtime_error("cannot read " + file.string());
  CsvTable t;
  std::string line;
  if (!std::getline(in, line)) return t;
  std::stringstream header(line);
  for (std::string name; std::getline(header, name, ',');) t.names.push_back(name);
  while (std::getline(in, line)) {
    std::vector<std::string> row;
    std::stringstream cells(line);
    for (std::string c; std::getline(cells, c, ',');) row.push_back(c);
    if (row.size() == t.names.size()) t.cells.push_back(std::move(row));
  }
  return t;
}

namespace {

void read_series(ExperimentRun& run) {
  if (!fs::exists(run.dir / "series.csv")) return;
  const CsvTable t = read_csv(run.dir / "series.csv");
  run.series_names = t.names;
  for (const auto& r : t.cells) {
    std::vector<double> row;
    for (const auto& c : r) row.push_back(std::strtod(c.c_str(), nullptr));
    run.series.push_back(std::move(row));
  }
}

}  // namespace

ExperimentRun run_experiment(const StepContext& ctx, const std::string& id, const std::string& config,
                             const ConfigEdit& edit, Section& section) {
  const fs::path source = ctx.examples / config;
  toml::table table;
  try {
    table = toml::parse_file(source.string());
  } catch (const toml::parse_error& e) {
    throw std::runtime_error("cannot read experiment config " + source.string() + ": " +
                             std::string(e.description()));
  }
  if (edit) edit(table, ctx.full);
  if (auto* output = table["output"].as_table()) output->erase("dir");
  std::ostringstream text;
  text << "# written by `lrchain reproduce --" << (ctx.full ? "full" : "quick") << "` from examples/"
       << config << "\n"
       << table << "\n";
  const fs::path configs = ctx.out / "configs";
  jobs::ensure_directory(configs);
  jobs::write_file_atomic(configs, id + ".toml", text.str());

  ExperimentRun run;
  run.dir = ctx.out / id;
  run_lrchain(ctx, {"simulate", "--config", (configs / (id + ".toml")).string(), "--out", run.dir.string(), "--json"},
              run.dir, "stdout", section.commands);
  run.summary = read_json(run.dir / "summary.json");
  read_series(run);
  section.links.push_back("configs/" + id + ".toml");
  section.links.push_back(id + "/summary.json");
  section.links.push_back(id + "/series.csv");
  return run;
}

}  // namespace lrchain::report

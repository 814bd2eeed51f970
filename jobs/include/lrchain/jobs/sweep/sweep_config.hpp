#pragma once
// A sweep config (`lrchain sweep --config sweep.toml`; docs/sweeps.md): which job, its base
// experiment config, where the results go, and the axes, read through the strict config layer
// (lrchain/config/strict_toml.hpp). The points are the grid of the axes (`layout = "grid"`, the
// last axis varying fastest) or the i-th values of every axis together (`layout = "list"`).
#include <cstddef>
#include <filesystem>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "lrchain/config/strict_toml.hpp"
#include "lrchain/jobs/sweep/job.hpp"

namespace lrchain::jobs::sweep {

struct Axis {
  std::string parameter;       // "bright.theta"
  std::vector<double> values;  // in order
};

struct SweepConfig {
  std::string name;              // `name`, or the file's stem
  std::string job;               // "bright", "drive", "modulated"
  std::filesystem::path base;    // the base experiment config (relative paths: to the sweep file)
  std::string base_text;         // its contents (part of the sweep's identity)
  std::string text;              // the sweep file's contents (recorded in the results)
  bool grid = true;              // layout
  std::vector<Axis> axes;
  std::filesystem::path output;  // results file (.h5)
  std::size_t csv_max_points = 10000;  // a CSV view next to it when the sweep has at most this many points
  double checkpoint_seconds = 30;      // the results file is rewritten at least this often
  std::string figure;                  // scalar drawn as log10 over a two-axis grid (empty: none)
  std::shared_ptr<const Job> base_job;  // the job of `base`, made (its model file loaded) by load_sweep_config

  std::size_t points() const;
  std::vector<std::size_t> shape() const;      // grid: one extent per axis; list: {points}
  Overrides overrides(std::size_t point) const;  // (parameter, value) of every axis at a point
};

// The schema of a sweep file (for the docs and the checks).
const lrchain::config::TableSchema& sweep_schema();
// The reference of every key as Markdown (docs/sweeps.md holds it).
std::string sweep_config_markdown();

// Reads and checks a sweep file and its base config: ConfigError (exit 2) naming the file, line and
// key for an unknown key, an unknown job or axis parameter, an empty range, list axes of different
// lengths, a base config of another job, a control character in a name, and a sweep whose results
// need more than the available memory with `ranks_on_node` ranks on rank 0's node (checked from the
// axes' counts before their values are generated; sweep_memory.hpp). A model-file base has its
// model loaded once (jobs::ModelSource with the front end's `compiler`; null: shipped model files
// only), and a missing or bad model file or an unknown `parameters.NAME` axis is a ConfigError too.
SweepConfig load_sweep_config(const std::filesystem::path& file, int ranks_on_node = 1,
                              std::shared_ptr<const ModelCompiler> compiler = nullptr);
// Why `output` cannot be a sweep's results file name (a control character, no file name, with a
// figure a quote or backslash in its name), or "" when it can.
std::string output_problem(const std::filesystem::path& output, bool figure);
// The job of a loaded sweep (its base config, checked; the job load_sweep_config made, sharing its
// model file, when there is one).
Job make_job(const SweepConfig& c);

// A one-axis "dark continue" or "bright continue" sweep's figure = "stability": its branches in the
// (axis, omega_b or the continued parameter) plane (sweep_figure.hpp).
bool draws_stability_figure(const SweepConfig& c);

}  // namespace lrchain::jobs::sweep

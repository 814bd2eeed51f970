// Reading TOML experiment configs (toml++) into run configurations.
#include "lrchain/sim/experiment_config.hpp"

#include "lrchain/errors.hpp"
#include "toml_reading.hpp"

namespace lrchain::sim {

namespace {

using config::read_long;
using config::read_number;
using config::read_numbers;

void read_bright(const toml::table& t, BrightRunConfig& c) {
  if (auto s = t["branch"].value<std::string>()) c.branch = parse_branch(*s);
  if (!read_number(t, "theta", c.theta)) throw InvalidParameter("theta", "[bright] needs theta");
  double d;
  if (read_number(t, "detuning", d)) c.detuning = d;
  read_number(t, "n0", c.n0);
  read_long(t, "N", c.N);
  read_number(t, "periods", c.periods);
  read_number(t, "sample_every", c.sample_every);
  read_number(t, "spacetime_every", c.spacetime_every);
  read_number(t, "error_window_end", c.error_window_end);
  long m = long(c.centre_window);
  if (read_long(t, "centre_window", m)) {
    if (m < 1) throw InvalidParameter("centre_window", "must be >= 1");
    c.centre_window = std::size_t(m);
  }
  if (auto b = t["ansatz_ends"].value<bool>()) c.ansatz_ends = *b;
  read_numbers(t, "snapshot_periods", c.snapshot_periods);
  read_number(t, "trailing_fit_start", c.trailing.fit_start);
  read_number(t, "trailing_gap", c.trailing.gap);
}

}  // namespace

ExperimentConfig load_experiment_config(const std::filesystem::path& file) {
  const toml::table root = config::parse_file(file);
  ExperimentConfig c;
  c.experiment = root["experiment"].value_or(std::string());
  c.name = root["name"].value_or(file.stem().string());
  Params p;
  IntegratorOptions integ;
  config::read_common(root, p, integ, c.out_dir);
  if (c.experiment == "bright") {
    c.bright.params = p;
    c.bright.integrator = integ;
    auto b = root["bright"].as_table();
    if (!b) throw InvalidParameter("bright", "config needs a [bright] table");
    read_bright(*b, c.bright);
    validate(c.bright);
  } else {
    throw InvalidParameter("experiment", "must be \"bright\" (got \"" + c.experiment + "\")");
  }
  return c;
}

}  // namespace lrchain::sim

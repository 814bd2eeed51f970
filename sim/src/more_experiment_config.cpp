// Reading the [drive] and [modulated] TOML configs (toml++).
#include "lrchain/sim/more_experiment_config.hpp"

#include "lrchain/errors.hpp"
#include "toml_reading.hpp"

namespace lrchain::sim {

using config::read_common;
using config::read_long;
using config::read_number;
using config::read_numbers;

std::string experiment_kind(const std::filesystem::path& file) {
  return config::parse_file(file)["experiment"].value_or(std::string());
}

DriveExperiment load_drive_config(const std::filesystem::path& file) {
  const toml::table root = config::parse_file(file);
  DriveExperiment x;
  x.name = root["name"].value_or(file.stem().string());
  read_common(root, x.run.params, x.run.integrator, x.out_dir);
  auto d = root["drive"].as_table();
  if (!d) throw InvalidParameter("drive", "config needs a [drive] table");
  read_long(*d, "beads", x.run.beads);
  read_number(*d, "amplitude", x.run.amplitude);
  read_number(*d, "omega0", x.run.omega0);
  read_number(*d, "ramp_rate", x.run.ramp_rate);
  read_number(*d, "t_m", x.run.t_m);
  read_number(*d, "t_end", x.run.t_end);
  read_number(*d, "sample_every", x.run.sample_every);
  read_number(*d, "spacetime_every", x.run.spacetime_every);
  read_numbers(*d, "snapshot_times", x.run.snapshot_times);
  read_number(*d, "front_fraction", x.run.front_fraction);
  read_number(*d, "front_fit_start", x.run.front_fit_start);
  read_number(*d, "front_fit_end", x.run.front_fit_end);
  validate(x.run);
  return x;
}

ModulatedExperiment load_modulated_config(const std::filesystem::path& file) {
  const toml::table root = config::parse_file(file);
  ModulatedExperiment x;
  x.run.name = root["name"].value_or(file.stem().string());
  read_common(root, x.run.params, x.run.integrator, x.out_dir);
  auto d = root["modulated"].as_table();
  if (!d) throw InvalidParameter("modulated", "config needs a [modulated] table");
  read_long(*d, "N", x.run.N);
  read_number(*d, "epsilon", x.run.epsilon);
  read_number(*d, "theta_waves", x.run.theta_waves);
  read_number(*d, "b", x.run.b);
  read_number(*d, "t_end", x.run.t_end);
  read_number(*d, "sample_every", x.run.sample_every);
  read_numbers(*d, "snapshot_times", x.run.snapshot_times);
  read_number(*d, "contrast_threshold", x.run.contrast_threshold);
  read_long(*d, "dark_window", x.run.dark_window);
  read_number(*d, "speed_fit_start", x.run.speed_fit_start);
  read_number(*d, "speed_fit_end", x.run.speed_fit_end);
  read_number(*d, "checkpoint_every", x.run.checkpoint_every);
  validate(x.run);
  return x;
}

}  // namespace lrchain::sim

// Reading checked [drive] and [modulated] TOML configs into their run configurations
// (more_experiment_config.hpp).
#include "lrchain/jobs/more_experiment_config.hpp"

#include "lrchain/jobs/experiment_config.hpp"
#include "located_validation.hpp"
#include "toml_reading.hpp"

namespace lrchain::jobs {

using namespace lrchain::sim;  // the numerics this job layer runs

namespace {

// The checked top level of a config that must be of `kind`.
config::CheckedTable checked_as(const config::Document& doc, const std::string& kind) {
  const std::string found = experiment_kind(doc);
  if (found != kind)
    throw config::ConfigError("config file '" + doc.source() + "' is a \"" + found + "\" experiment; this reader takes \"" +
                                  kind + "\" only",
                              doc.source(), 0, "", "experiment");
  return config::check(doc, experiment_schema(kind));
}

}  // namespace

DriveExperiment load_drive_config(const config::Document& doc) {
  const config::CheckedTable root = checked_as(doc, "drive");
  DriveExperiment x;
  x.name = config::config_name(root);
  config::read_common(root, x.run.params, x.run.integrator, x.out_dir);
  {
    const auto d = root.table("drive");  // a required table
    d->read("sites", x.run.beads);
    d->read("amplitude", x.run.amplitude);
    d->read("omega0", x.run.omega0);
    d->read("ramp_rate", x.run.ramp_rate);
    d->read("switch_off_time", x.run.t_m);
    d->read("t_end", x.run.t_end);
    d->read("sample_every", x.run.sample_every);
    d->read("spacetime_every", x.run.spacetime_every);
    d->read("snapshot_times", x.run.snapshot_times);
    d->read("front_fraction", x.run.front_fraction);
    d->read("front_fit_start", x.run.front_fit_start);
    d->read("front_fit_end", x.run.front_fit_end);
    d->read("checkpoint_every", x.run.checkpoint_every);
  }
  config::validate_located(root, "drive", [&x] { validate(x.run); });
  return x;
}

ModulatedExperiment load_modulated_config(const config::Document& doc) {
  const config::CheckedTable root = checked_as(doc, "modulated");
  ModulatedExperiment x;
  x.run.name = config::config_name(root);
  config::read_common(root, x.run.params, x.run.integrator, x.out_dir);
  {
    const auto d = root.table("modulated");  // a required table
    d->read("sites", x.run.N);
    d->read("epsilon", x.run.epsilon);
    d->read("theta_waves", x.run.theta_waves);
    d->read("modulation_depth", x.run.b);
    d->read("t_end", x.run.t_end);
    d->read("sample_every", x.run.sample_every);
    d->read("snapshot_times", x.run.snapshot_times);
    d->read("contrast_threshold", x.run.contrast_threshold);
    d->read("dark_window", x.run.dark_window);
    d->read("speed_fit_start", x.run.speed_fit_start);
    d->read("speed_fit_end", x.run.speed_fit_end);
    d->read("checkpoint_every", x.run.checkpoint_every);
  }
  config::validate_located(root, "modulated", [&x] { validate(x.run); });
  return x;
}

DriveExperiment load_drive_config(const std::filesystem::path& file) {
  return load_drive_config(config::Document::from_file(file));
}

ModulatedExperiment load_modulated_config(const std::filesystem::path& file) {
  return load_modulated_config(config::Document::from_file(file));
}

}  // namespace lrchain::jobs

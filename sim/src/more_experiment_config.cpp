// Reading the [drive] and [modulated] TOML configs (toml++).
#include "lrchain/sim/more_experiment_config.hpp"

#include <cmath>
#include <stdexcept>
#include <toml++/toml.h>

#include "lrchain/errors.hpp"
#include "lrchain/numeric_parse.hpp"

namespace lrchain::sim {

namespace {

toml::table parse(const std::filesystem::path& file) {
  try {
    return toml::parse_file(file.string());
  } catch (const toml::parse_error& e) {
    throw std::runtime_error("cannot read config '" + file.string() + "': " +
                             std::string(e.description()));
  }
}

bool read_number(const toml::table& t, const std::string& key, double& out) {
  const toml::node* n = t.get(key);
  if (!n) return false;
  if (auto v = n->value<double>()) { out = *v; return true; }
  if (auto s = n->value<std::string>()) { out = parse_number(*s, key); return true; }
  throw InvalidParameter(key, "must be a number or a number string such as \"1/3\" or \"pi/2\"");
}

bool read_long(const toml::table& t, const std::string& key, long& out) {
  double v;
  if (!read_number(t, key, v)) return false;
  if (v != std::floor(v)) throw InvalidParameter(key, "must be an integer");
  out = long(v);
  return true;
}

void read_numbers(const toml::table& t, const std::string& key, std::vector<double>& out) {
  if (auto arr = t[key].as_array()) {
    out.clear();
    for (const auto& e : *arr) {
      auto v = e.value<double>();
      if (!v) throw InvalidParameter(key, "must be an array of numbers");
      out.push_back(*v);
    }
  }
}

void read_common(const toml::table& root, Params& p, IntegratorOptions& o, std::string& out_dir) {
  if (auto m = root["model"].as_table()) {
    read_number(*m, "rho", p.rho);
    read_number(*m, "kappa", p.kappa);
    read_number(*m, "delta0", p.delta0);
    read_number(*m, "alpha", p.alpha);
  }
  if (auto i = root["integrator"].as_table()) {
    if (auto s = (*i)["stepper"].value<std::string>()) o.stepper = parse_stepper(*s);
    read_number(*i, "abs_tol", o.abs_tol);
    read_number(*i, "rel_tol", o.rel_tol);
    read_number(*i, "dt", o.dt);
  }
  if (auto od = root["output"].as_table()) out_dir = (*od)["dir"].value_or(std::string());
}

}  // namespace

std::string experiment_kind(const std::filesystem::path& file) {
  return parse(file)["experiment"].value_or(std::string());
}

DriveExperiment load_drive_config(const std::filesystem::path& file) {
  const toml::table root = parse(file);
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
  const toml::table root = parse(file);
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

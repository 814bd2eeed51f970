// Reading TOML experiment configs (toml++) into run configurations.
#include "lrchain/sim/experiment_config.hpp"

#include <stdexcept>
#include <toml++/toml.h>

#include "lrchain/errors.hpp"
#include "lrchain/numeric_parse.hpp"

namespace lrchain::sim {

namespace {

// A number given as TOML float/integer or as a string in the shared syntax.
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

void read_model(const toml::table& t, Params& p) {
  read_number(t, "rho", p.rho);
  read_number(t, "kappa", p.kappa);
  read_number(t, "delta0", p.delta0);
  read_number(t, "alpha", p.alpha);
}

void read_integrator(const toml::table& t, IntegratorOptions& o) {
  if (auto s = t["stepper"].value<std::string>()) o.stepper = parse_stepper(*s);
  read_number(t, "abs_tol", o.abs_tol);
  read_number(t, "rel_tol", o.rel_tol);
  read_number(t, "dt", o.dt);
}

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
  if (auto arr = t["snapshot_periods"].as_array()) {
    c.snapshot_periods.clear();
    for (const auto& e : *arr) {
      auto v = e.value<double>();
      if (!v) throw InvalidParameter("snapshot_periods", "must be an array of numbers");
      c.snapshot_periods.push_back(*v);
    }
  }
}

}  // namespace

ExperimentConfig load_experiment_config(const std::filesystem::path& file) {
  toml::table root;
  try {
    root = toml::parse_file(file.string());
  } catch (const toml::parse_error& e) {
    throw std::runtime_error("cannot read config '" + file.string() + "': " +
                             std::string(e.description()));
  }
  ExperimentConfig c;
  c.experiment = root["experiment"].value_or(std::string());
  c.name = root["name"].value_or(file.stem().string());
  Params p;
  if (auto m = root["model"].as_table()) read_model(*m, p);
  IntegratorOptions integ;
  if (auto i = root["integrator"].as_table()) read_integrator(*i, integ);
  if (auto o = root["output"].as_table()) c.out_dir = (*o)["dir"].value_or(std::string());
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

// Shared TOML readers of the experiment configs (toml_reading.hpp).
#include "toml_reading.hpp"

#include <cmath>
#include <stdexcept>

#include "lrchain/errors.hpp"
#include "lrchain/numeric_parse.hpp"

namespace lrchain::sim::config {

toml::table parse_file(const std::filesystem::path& file) {
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

}  // namespace lrchain::sim::config

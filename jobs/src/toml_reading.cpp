// The tables every simulate config shares, as schemas, and reading them (toml_reading.hpp).
#include "toml_reading.hpp"

#include <cmath>
#include <filesystem>

namespace lrchain::jobs::config {

using namespace lrchain::sim;  // the numerics this job layer runs

namespace {

// A default as the examples write it: "1/3", "4/9" for small exact fractions, else the number.
std::string default_text(double v) {
  if (v != std::floor(v))
    for (int q = 2; q <= 12; ++q) {
      const double p = std::round(v * q);
      if (p / q == v) return number_text(p) + "/" + std::to_string(q);
    }
  return number_text(v);
}

}  // namespace

NumberRange range_of(const PhysicalRange& r) { return NumberRange::between(r.min, r.max, r.min_open, r.max_open); }

std::shared_ptr<const TableSchema> model_schema(const Params& d) {
  const auto key = [](const PhysicalRange& r, double default_value) {
    return number(r.name, range_of(r), default_text(default_value), r.meaning);
  };
  return std::make_shared<const TableSchema>(TableSchema{
      "the resonant chain's parameters (Sec. 2)",
      {key(rho_range, d.rho), key(kappa_range, d.kappa), key(delta0_range, d.delta0), key(alpha_range, d.alpha)},
      std::nullopt});
}

std::vector<std::string> all_steppers() { return {"rkf78", "dopri5", "symplectic", "srkn11b", "srkn14a", "ss17"}; }

std::shared_ptr<const TableSchema> integrator_schema(const IntegratorOptions& d, const std::vector<std::string>& steppers) {
  return std::make_shared<const TableSchema>(TableSchema{
      "the time integration (Boost.Odeint)",
      {choice("stepper", steppers, std::string(to_string(d.stepper)),
              "rkf78, dopri5 (adaptive); symplectic (McLachlan 4), srkn11b, srkn14a (Blanes-Moan 6), ss17 "
              "(McLachlan 8): fixed step, autonomous systems only"),
       number("abs_tol", NumberRange::between(0, 1, true, true), number_text(d.abs_tol),
              "absolute local error tolerance (adaptive steppers)"),
       number("rel_tol", NumberRange::between(0, 1, false, true), number_text(d.rel_tol),
              "relative local error tolerance (adaptive steppers)"),
       number("dt", NumberRange::positive(),
              d.automatic_dt ? "automatic for fixed-step steppers (energy-error probe), " + number_text(d.dt) + " for adaptive"
                             : number_text(d.dt),
              "initial step (adaptive) or largest step (fixed-step steppers)")},
      std::nullopt});
}

std::shared_ptr<const TableSchema> output_schema() {
  return std::make_shared<const TableSchema>(TableSchema{
      "where the data and figures go",
      {string("dir", "none", "output directory (the command line's --out overrides it)")},
      std::nullopt});
}

TableSchema top_level_schema(const std::string& kind, const Params& model_defaults,
                             const IntegratorOptions& integrator_defaults, const std::vector<std::string>& steppers,
                             std::shared_ptr<const TableSchema> experiment_table) {
  return TableSchema{"a \"" + kind + "\" experiment",
                     {choice("experiment", {kind}, "", "which experiment this file describes").require(),
                      string("name", "the file name without .toml", "a label for the run, copied to the JSON summary"),
                      table("model", model_schema(model_defaults)),
                      table(kind, std::move(experiment_table)).require(),
                      table("integrator", integrator_schema(integrator_defaults, steppers)),
                      table("output", output_schema())},
                     std::nullopt};
}

void read_common(const CheckedTable& root, Params& p, IntegratorOptions& o, std::string& out_dir) {
  if (auto m = root.table("model")) {
    m->read("rho", p.rho);
    m->read("kappa", p.kappa);
    m->read("delta0", p.delta0);
    m->read("alpha", p.alpha);
  }
  if (auto i = root.table("integrator")) {
    std::string stepper;
    if (i->read("stepper", stepper)) o.stepper = parse_stepper(stepper);
    i->read("abs_tol", o.abs_tol);
    i->read("rel_tol", o.rel_tol);
    if (i->read("dt", o.dt)) o.automatic_dt = false;
  }
  if (auto od = root.table("output")) od->read("dir", out_dir);
}

std::string config_name(const CheckedTable& root) {
  std::string name = std::filesystem::path(root.source()).stem().string();
  root.read("name", name);
  return name;
}

}  // namespace lrchain::jobs::config

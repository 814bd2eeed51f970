// validate(DarkConfig): every option of a dark job, its memory and its output directory, checked
// before any Newton iteration and before anything is written (dark_job.hpp).
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numbers>
#include <optional>

#include <fmt/format.h>

#include "../breather_outputs.hpp"
#include "dark_keys.hpp"
#include "lrchain/ansatz/dark_breather.hpp"
#include "lrchain/checked_number.hpp"
#include "lrchain/config/option_caps.hpp"
#include "lrchain/dispersion.hpp"
#include "lrchain/jobs/dark_job.hpp"
#include "lrchain/sim/dark/dark_ansatz.hpp"
#include "lrchain/sim/resource_estimate.hpp"

namespace lrchain::jobs::dark {

using namespace lrchain::sim::dark;

namespace {

// The top of the highest linear band (theta = 0 or pi) of the job's lattice.
double highest_band_frequency(const DarkConfig& c) {
  double top = 0;
  for (const double theta : {0.0, std::numbers::pi}) {
    if (!c.model) {
      top = std::max(top, dispersion_omega(c.params, Branch::optical, theta));
      continue;
    }
    for (Index b = 0; b < Index(c.model->definition().branch_names.size()); ++b) try {
        top = std::max(top, coefficients_from_evaluators(*c.model, b, theta).omega);
      } catch (const InvalidParameter&) {  // no real frequency there (an acoustic branch at theta = 0)
      }
  }
  return top;
}

// The resonant chain: parameters, edge and omega_b (eq:xy_app needs (omega - omega_b) > 0), window.
void validate_chain(const DarkConfig& c) {
  validate(c.params);
  with_config_keys([&] {
    make_dark_breather_ansatz(c.params, parse_branch(c.branch.empty() ? "optical" : c.branch), c.omega_b);
  });
  parse_dark_center(c.center);
  parse_shooting_mode(c.mode);
  if (dark_sites(c) % 2 == 0)
    throw InvalidParameter("sites", "must be an odd integer >= 9 (a staggered dark breather fits "
                                    "periodic ends only on an odd number of sites)");
  if (c.step == DarkStep::branch) {
    // The continuation adapts its step between 1e-5 and 1; it starts at omega_b, which must lie
    // inside the window [omega_min, omega_max] it stops outside of.
    checked_finite(c.omega_max, "omega_max");
    if (c.omega_max != 0 && !(c.omega_max > 0))
      throw InvalidParameter("omega_max", "must be 0 (the band edge) or a frequency above omega-b");
    with_config_keys([&] {
      validate_continuation_window(c.params, c.omega_b, c.ds, c.omega_min,
                                   c.omega_max > 0 ? std::optional<double>(c.omega_max) : std::nullopt);
    });
  }
}

// Newton's and Floquet's matrices, the recorded orbit and the evolution's snapshots of the chain.
sim::ResourceEstimate chain_estimate(const DarkConfig& c, double periods) {
  const ShootingMode mode = parse_shooting_mode(c.mode);
  const DarkCenter center = parse_dark_center(c.center);
  const double period = 2 * std::numbers::pi / c.omega_b;
  const double shooting_time = mode == ShootingMode::full || c.step == DarkStep::floquet
                                   ? period : (center == DarkCenter::site ? period / 2 : period / 4);
  const bool floquet = c.step == DarkStep::floquet || (c.step == DarkStep::branch && c.branch_floquet);
  return sim::estimate_dark_breather(dark_sites(c), floquet, shooting_time, periods);
}

// A model file: its defocusing edge (or the branch given), omega_b on its gap side, sites, window.
void validate_model(const DarkConfig& c) {
  if (c.kernels == nullptr) throw InvalidParameter("model", "needs its lattice kernels (DarkConfig::kernels)");
  parse_dark_center(c.center);
  parse_shooting_mode(c.mode);
  if (c.krylov.solver == "krylov" && c.step == DarkStep::branch)
    throw InvalidParameter("solver", "continue needs the dense Jacobian: dense or auto, got krylov");
  if (c.krylov.solver == "krylov" && parse_shooting_mode(c.mode) == ShootingMode::full)
    throw InvalidParameter("solver", "krylov solves the reversible shooting: mode full needs dense or auto");
  if (c.full_monodromy)
    throw InvalidParameter("full_monodromy", "with a model file the Floquet multipliers always come from the "
                                             "full-period monodromy");
  const Model& model = *c.model;
  const std::optional<Index> given = c.branch.empty() ? std::nullopt : std::optional(model.branch(c.branch));
  const DarkAnsatz ansatz = with_config_keys(
      [&] { return make_dark_ansatz(model, *c.kernels, defocusing_edge(model, given), c.omega_b); });
  check_dark_sites(ansatz, c.sites.value_or(default_dark_sites(ansatz.theta)));
  if (c.step == DarkStep::branch && c.parameter != "omega_b")  // a model parameter at fixed omega_b
    check_continued_parameter(model, c.parameter, c.to);
  if (c.step == DarkStep::branch) {
    checked_finite(c.ds, "ds");
    if (!(c.ds > 0 && c.ds <= 1)) throw InvalidParameter("ds", "must be in (0, 1] (it adapts within [1e-5, 1])");
    checked_finite(c.omega_min, "omega_min");
    checked_finite(c.omega_max, "omega_max");
    if (!(c.omega_min < c.omega_b)) throw InvalidParameter("omega_min", "must lie below omega-b");
    if (c.omega_max != 0 && !(c.omega_max > c.omega_b))
      throw InvalidParameter("omega_max",
                             "must be 0 (the band edge, or none above it) or a frequency above omega-b");
  }
}

// The same for a model: the estimate counts two fields per site, scaled to the model's fields.
sim::ResourceEstimate model_estimate(const DarkConfig& c, double periods) {
  if (c.step != DarkStep::branch && parse_shooting_mode(c.mode) == ShootingMode::reversible &&
      use_krylov(c.krylov, dark_sites(c)))
    return sim::estimate_krylov_breather(double(dark_sites(c)) * double(c.kernels->fields), c.kernels->fields,
                                         double(c.krylov.krylov_band),
                                         double(sim::dark::NewtonKrylovOptions{}.gmres_restart + 2 * c.krylov.floquet_count + 20));
  const double sites = double(dark_sites(c)) * double(c.kernels->fields) / 2.0;
  return sim::estimate_dark_breather(sites, true, 2 * std::numbers::pi / c.omega_b, periods);
}

}  // namespace

Index dark_sites(const DarkConfig& c) {
  if (c.sites) return *c.sites;
  if (!c.model) return default_dark_sites(std::numbers::pi);
  const std::optional<Index> given = c.branch.empty() ? std::nullopt : std::optional(c.model->branch(c.branch));
  return default_dark_sites(defocusing_edge(*c.model, given).theta);
}

void validate(const DarkConfig& c) {
  if (!c.model && c.parameter != "omega_b")
    throw InvalidParameter("parameter", "must be omega_b for the paper chain (continue a model file's parameters with "
                                        "a model, e.g. the shipped resonant_chain), got '" + c.parameter + "'");
  if (c.step == DarkStep::branch && c.parameter == "omega_b" && c.to) {
    checked_finite(*c.to, "to");
    if (!(*c.to > 0 && *c.to != c.omega_b))
      throw InvalidParameter("to", "must be a frequency > 0 other than omega-b (where the continuation in omega_b ends)");
    const double top = highest_band_frequency(c);
    if (!(*c.to <= 2 * top))
      throw InvalidParameter("to", fmt::format("must be at most twice the top of the highest band, {:.10g}", 2 * top));
  }
  if (c.sites) config::checked_option(double(*c.sites), config::dark_sites, "sites");
  if (!(c.tolerance > 0 && c.tolerance < 1)) throw InvalidParameter("tolerance", "must be in (0, 1)");
  if (c.max_iterations < 1) throw InvalidParameter("max_iterations", "must be an integer >= 1");
  if (c.format != "csv" && c.format != "hdf5") throw InvalidParameter("format", "must be csv or hdf5");
  if (c.step == DarkStep::branch) config::checked_option(double(c.points), config::dark_points, "points");
  validate(c.krylov);
  if (!c.model && c.krylov.solver == "krylov")
    throw InvalidParameter("solver", "krylov needs a model file (e.g. the shipped resonant_chain); the paper chain's "
                                     "own shooting is dense");
  if (c.model) validate_model(c);
  else validate_chain(c);
  double periods = 0;
  if (c.step == DarkStep::evolve) {
    const double period = 2 * std::numbers::pi / c.omega_b;
    if (!(std::isfinite(c.t_end) && std::isfinite(period) && c.t_end >= period))
      throw InvalidParameter("t_end", fmt::format("must be a finite time >= one period T_b = 2 pi/omega_b = {:.6g} "
                                                  "(dimensionless time of Sec. 2)", period));
    periods = double(config::checked_option_count(c.t_end, period, config::dark_periods, "t_end"));
    config::checked_option(double(c.samples), config::dark_samples, "samples");
    check_perturbation(c.perturb, c.perturb_size, c.seed);
  }
  const sim::ResourceEstimate e = c.model ? model_estimate(c, periods) : chain_estimate(c, periods);
  if (e.dominant == "period" && !c.model)  // (a model's refusal names sites, as `dark --model` did)
    sim::check_memory(e, c.max_memory, "omega_b", "raise omega_b (a shorter period T_b)");
  else if (e.dominant == "periods")
    sim::check_memory(e, c.max_memory, "t_end", "lower t_end");
  else
    sim::check_memory(e, c.max_memory, "sites", "lower sites");
  check_output_directory(e, c.out);
}

}  // namespace lrchain::jobs::dark

// validate(BrightBreatherConfig): every option, the non-resonance of omega_b and its focusing edge,
// the memory and the output directory, checked before any Newton iteration (bright_breather_job.hpp).
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numbers>

#include <fmt/format.h>

#include "../breather_outputs.hpp"
#include "lrchain/ansatz/dark_breather.hpp"
#include "lrchain/checked_number.hpp"
#include "lrchain/config/option_caps.hpp"
#include "lrchain/errors.hpp"
#include "lrchain/jobs/bright_breather_job.hpp"
#include "lrchain/sim/bright/bright_seed.hpp"
#include "lrchain/sim/resource_estimate.hpp"

namespace lrchain::jobs::bright_breather {

namespace {
// The largest omega_b accepted, in units of the top of the highest linear band.
constexpr double omega_b_cap = 10;
// The most periods evolve integrates.
constexpr Index max_periods = 1'000'000;
}  // namespace

namespace {
// start = anti-continuum: an on-site model (a translation-invariant one has no uncoupled limit) and a
// coupling parameter whose range holds 0.
void check_anti_continuum(const Model& model, const std::string& coupling) {
  if (model.definition().mean_flow)
    throw InvalidParameter("start", fmt::format("anti-continuum needs an on-site model; {} is translation-invariant "
                                                "(no cell oscillates on its own when its bonds are removed): use nls",
                                                model.name()));
  std::string names;
  for (const auto& p : model.definition().parameters) {
    if (p.name == coupling) {
      if (!p.contains(0))
        throw InvalidParameter("coupling", fmt::format("{} must have 0 in its range {} (the uncoupled lattice)", coupling,
                                                       p.range_text));
      return;
    }
    names += (names.empty() ? "" : ", ") + p.name;
  }
  throw InvalidParameter("coupling", fmt::format("must be one of the parameters of {} ({}), got '{}'", model.name(),
                                                 names, coupling));
}
}  // namespace

void validate(const BrightBreatherConfig& c) {
  if (c.model == nullptr || c.kernels == nullptr)
    throw InvalidParameter("model", "needs a loaded model and its lattice kernels (model, kernels)");
  if (!(std::isfinite(c.omega_b) && c.omega_b > 0))
    throw InvalidParameter("omega_b", "must be a finite frequency > 0 (dimensionless)");
  config::checked_option(double(c.sites), config::dark_sites, "sites");
  sim::bright::check_bright_sites(c.sites);
  parse_dark_center(c.center);
  if (c.start != "nls" && c.start != "anti-continuum") throw InvalidParameter("start", "must be nls or anti-continuum");
  if (c.start == "anti-continuum") check_anti_continuum(*c.model, c.coupling);
  if (!(c.tolerance > 0 && c.tolerance < 1)) throw InvalidParameter("tolerance", "must be in (0, 1)");
  if (c.max_iterations < 1) throw InvalidParameter("max_iterations", "must be an integer >= 1");
  if (!(c.tail_tolerance > 0 && c.tail_tolerance < 1)) throw InvalidParameter("tail_tolerance", "must be in (0, 1)");
  if (!(c.unit_tolerance > 0 && c.unit_tolerance < 1)) throw InvalidParameter("unit_tolerance", "must be in (0, 1)");
  if (!(c.locate_tolerance >= 0 && c.locate_tolerance < 1))
    throw InvalidParameter("locate_tolerance", "must be in [0, 1) (0: crossings bracketed, not located)");
  if (c.format != "csv" && c.format != "hdf5") throw InvalidParameter("format", "must be csv or hdf5");
  if (c.step == BrightStep::branch) {
    config::checked_option(double(c.points), config::dark_points, "points");
    if (!(std::isfinite(c.ds) && c.ds > 0 && c.ds <= 1)) throw InvalidParameter("ds", "must be in (0, 1] (it adapts within [1e-5, 1])");
  }
  if (c.step == BrightStep::branch && c.parameter != "omega_b") check_continued_parameter(*c.model, c.parameter, c.to);
  if (c.step == BrightStep::branch && c.parameter == "omega_b" && c.to) {
    checked_finite(*c.to, "to");
    const auto bands = sim::bright::linear_bands(*c.model);
    auto [low, high] = sim::bright::non_resonant_window(bands, c.omega_b);
    double top = 0;  // above every band the window is unbounded: at most twice the highest frequency
    for (const auto& b : bands) top = std::max(top, b.highest);
    high = std::min(high, 2 * top);
    if (!(*c.to > low && *c.to < high && *c.to != c.omega_b))
      throw InvalidParameter("to", fmt::format("must differ from omega_b = {} and lie in its non-resonant window "
                                               "({:.10g}, {:.10g}) (no harmonic of omega_b in a band there)",
                                               c.omega_b, low, high));
  }
  if (c.step == BrightStep::evolve) {
    if (c.periods < 1 || c.periods > max_periods)
      throw InvalidParameter("periods", fmt::format("must be an integer in [1, {}]", max_periods));
    check_perturbation(c.perturb, c.perturb_size, c.seed);
  }
  validate(c.krylov);
  if (c.step == BrightStep::branch && c.krylov.solver == "krylov")
    throw InvalidParameter("solver", "continue needs the dense Jacobian: dense or auto, got krylov");
  const Model& model = *c.model;
  const std::optional<Index> branch = c.branch.empty() ? std::nullopt : std::optional(model.branch(c.branch));
  const auto bands = sim::bright::linear_bands(model);
  double top = 0;
  for (const auto& band : bands) top = std::max(top, band.highest);
  if (!(c.omega_b <= omega_b_cap * top))
    throw InvalidParameter("omega_b", fmt::format("must be at most {:g} times the top of the highest band, {:.10g} (the "
                                                  "NLS seed, an expansion about a band edge, does not reach a breather "
                                                  "that far beyond the bands)", omega_b_cap, omega_b_cap * top));
  sim::bright::check_non_resonance(bands, c.omega_b);
  sim::bright::focusing_edge(model, branch, c.omega_b);
  const double sites = double(c.sites) * double(c.kernels->fields) / 2.0;  // the estimate counts two fields per site
  const double positions = double(c.sites) * double(c.kernels->fields);
  const sim::ResourceEstimate e =
      c.step != BrightStep::branch && use_krylov(c.krylov, c.sites)
          ? sim::estimate_krylov_breather(positions, c.kernels->fields, double(c.krylov.krylov_band),
                                          double(sim::dark::NewtonKrylovOptions{}.gmres_restart + 2 * c.krylov.floquet_count + 20))
          : sim::estimate_dark_breather(sites, true, 2 * std::numbers::pi / c.omega_b, 0);
  sim::check_memory(e, c.max_memory, "sites", "lower sites");
  check_output_directory(e, c.out);
}

}  // namespace lrchain::jobs::bright_breather

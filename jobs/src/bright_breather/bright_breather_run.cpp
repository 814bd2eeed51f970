// run(BrightBreatherConfig): the bands and harmonics checked, the focusing edge and its NLS seed,
// Newton on the time-reversible shooting shared with the dark breathers, the localization check,
// and (floquet) the multipliers of the full-period monodromy (bright_breather_job.hpp).
#include <algorithm>
#include <chrono>
#include <functional>
#include <cmath>
#include <numbers>
#include <tuple>

#include <fmt/format.h>

#include "../breather_outputs.hpp"
#include "lrchain/errors.hpp"
#include "lrchain/jobs/bright_breather_job.hpp"
#include "lrchain/sim/bright/anti_continuum.hpp"
#include "lrchain/sim/bright/bright_seed.hpp"
#include "lrchain/sim/bright/fundamental_period.hpp"
#include "lrchain/sim/dark/contact_bonds.hpp"
#include "lrchain/sim/dark/parameter_shooting.hpp"
#include "lrchain/sim/dark/shooting.hpp"
#include "lrchain/sim/model_lattice_bloch.hpp"

namespace lrchain::jobs::bright_breather {

using namespace lrchain::sim::bright;

namespace {

sim::dark::NewtonOptions newton_options(const BrightBreatherConfig& c, const BrightBreatherHooks& hooks) {
  sim::dark::NewtonOptions o;
  o.tolerance = c.tolerance;
  o.max_iterations = c.max_iterations;
  o.progress = hooks.newton_progress;
  return o;
}

// The mass of every position of the displacement-form state, field-major (the symplectic form's weights).
Eigen::VectorXd position_masses(const lrchain_lattice_kernels& kernels, const std::vector<double>& parameters,
                                Index sites) {
  std::vector<double> field_mass(std::size_t(kernels.fields));
  kernels.masses(parameters.data(), field_mass.data());
  Eigen::VectorXd masses(kernels.fields * sites);
  for (Index f = 0; f < kernels.fields; ++f) masses.segment(f * sites, sites).setConstant(field_mass[std::size_t(f)]);
  return masses;
}

// The Krein signatures of the multipliers on the upper unit circle (krein_signature.hpp), in the
// lattice's form (strain: lifted to displacements).
std::vector<KreinMultiplier> krein_of(const Eigen::MatrixXd& monodromy, const std::vector<double>& parameters,
                                      double trivial_distance, const BrightBreatherConfig& c, bool mean_flow) {
  const Eigen::VectorXd masses = position_masses(*c.kernels, parameters, c.sites);
  return mean_flow ? strain_krein_signatures(monodromy, masses, c.sites, c.unit_tolerance, trivial_distance)
                   : krein_signatures(monodromy, masses, c.unit_tolerance, trivial_distance);
}

// The kept branch points as the bifurcation detector sees them: arclength |d(Z(0), omega_b)| summed
// from the first point, slope, norm and (with Floquet) the real multipliers beyond +1 and -1.
std::vector<BranchSample> branch_samples(const BrightBreatherResult& r, double unit_tolerance) {
  std::vector<BranchSample> samples;
  double s = 0;
  for (std::size_t k = 0; k < r.branch_profiles.size(); ++k) {
    const sim::dark::BranchPoint& p = r.branch.points[k];
    if (k > 0) {
      const sim::dark::BranchPoint& q = r.branch.points[k - 1];
      s += std::sqrt((p.z0 - q.z0).squaredNorm() + (p.parameter - q.parameter) * (p.parameter - q.parameter));
    }
    BranchSample sample{s, p.parameter, p.tangent_omega, r.branch_profiles[k].norm_squared, std::nullopt, std::nullopt,
                        std::nullopt, std::nullopt};
    if (k < r.branch_floquets.size()) {
      sample.real_unstable = real_multipliers_beyond(r.branch_floquets[k], +1, unit_tolerance);
      sample.period_doubling = real_multipliers_beyond(r.branch_floquets[k], -1, unit_tolerance);
      sample.period_tripling = multipliers_beyond_two_thirds(r.branch_floquets[k]);
      sample.oscillatory = r.branch_floquets[k].multipliers.oscillatory;
    }
    samples.push_back(sample);
  }
  return samples;
}

// The localization check of config c: its tail tolerance and where its family's centre lies on x_0.
BrightProfileOptions bright_profile_options(const BrightBreatherConfig& c) {
  BrightProfileOptions o;
  o.tail_tolerance = c.tail_tolerance;
  o.centre_position = dark_center_n0(parse_dark_center(c.center)) + (c.model->definition().mean_flow ? 0.5 : 0.0);
  return o;
}

// The breather re-solved on `shooting` at omega_b by dense Newton from `guess`, with its Floquet
// analysis, or nullopt when Newton fails, its zero is no localized breather or lies farther than 10% of
// the guess's peak from it (another family, not the branch between the bracket's ends).
std::optional<CrossingSolution> resolved_breather(const sim::dark::DarkShooting& shooting, double omega_b,
                                                  const Eigen::VectorXd& guess, const BrightBreatherConfig& c,
                                                  bool mean_flow) {
  BreatherSolverOptions dense = c.krylov;
  dense.solver = "dense";
  std::optional<KrylovRecord> record;
  const sim::dark::NewtonResult n = solve_breather(shooting, guess, omega_b, newton_options(c, {}), dense, record);
  if (!n.converged || (n.q - guess).lpNorm<Eigen::Infinity>() > 0.1 * guess.lpNorm<Eigen::Infinity>())
    return std::nullopt;
  const BrightProfile profile = inspect_bright_profile(n.q, c.sites, bright_profile_options(c));
  if (!profile.localized) return std::nullopt;
  return CrossingSolution{n.q, bright_floquet(shooting.monodromy(n.q, omega_b), mean_flow, {c.unit_tolerance}),
                          profile.norm_squared};
}

// Each multiplier crossing of the branch located by bisection in the continued parameter between its
// bracketing points (locate_crossing), `solve` re-solving the breather at a value of it from Z(0)
// interpolated linearly. Crossings in an interval with a fold stay bracketed (the parameter is not
// monotone there).
void locate_crossings(const BrightBreatherConfig& c, const CrossingSolver& solve, BrightBreatherResult& r) {
  if (c.locate_tolerance <= 0 || r.branch_floquets.size() != r.branch.points.size()) return;
  for (BranchBifurcation& b : r.bifurcations) {
    if (b.kind == "fold") continue;
    const bool fold_here = std::any_of(r.bifurcations.begin(), r.bifurcations.end(),
                                       [&](const BranchBifurcation& f) { return f.kind == "fold" && f.index == b.index; });
    if (fold_here) continue;
    const std::size_t k = std::size_t(b.index);
    const sim::dark::BranchPoint &p = r.branch.points[k], &q = r.branch.points[k + 1];
    locate_crossing(b, p.parameter, p.z0, r.branch_floquets[k], q.parameter, q.z0, r.branch_floquets[k + 1], solve,
                    c.unit_tolerance, c.locate_tolerance);
  }
}

// The continuation of a bright breather (omega_b or a model parameter) from config c.
sim::dark::ContinuationOptions continuation_options(const BrightBreatherConfig& c) {
  sim::dark::ContinuationOptions o;
  o.ds = c.ds;
  o.max_points = c.points;
  o.tolerance = c.tolerance;
  o.floquet = false;  // the bright Floquet analysis of keep_bright_points, with the trivial multipliers removed
  return o;
}

// Keeps the branch points up to the first that is no localized breather (branch.stop_reason says
// which), each with its profile and (branch_floquet) its multipliers and Krein signatures on the
// lattice `shooting_at(point)` gives at that point's parameters; then the bifurcations.
void keep_bright_points(const BrightBreatherConfig& c,
                        const std::function<std::vector<double>(const sim::dark::BranchPoint&)>& parameters_at,
                        const sim::dark::ContactBonds& contacts, BrightBreatherResult& r) {
  const BrightProfileOptions profile_options = bright_profile_options(c);
  for (std::size_t k = 0; k < r.branch.points.size(); ++k) {
    const sim::dark::BranchPoint& p = r.branch.points[k];
    BrightProfile profile = inspect_bright_profile(p.z0, c.sites, profile_options);
    if (!profile.localized) {
      r.branch.stop_reason = fmt::format("the branch point at {} = {:.6f} is no bright breather: {}", c.parameter,
                                         p.parameter, profile.reason);
      r.branch.points.resize(k);
      r.branch.turning_points.clear();  // those of the points kept: d omega_b / ds changing sign
      for (std::size_t j = 1; j < k; ++j)
        if ((r.branch.points[j].tangent_omega > 0) != (r.branch.points[j - 1].tangent_omega > 0))
          r.branch.turning_points.push_back(r.branch.points[j].parameter);
      break;
    }
    r.branch_profiles.push_back(std::move(profile));
    if (!c.branch_floquet) continue;
    const std::vector<double> parameters = parameters_at(p);
    const sim::dark::DarkShooting shooting(*c.kernels, parameters, c.sites, r.edge.mean_flow,
                                           sim::dark::ShootingMode::reversible, {}, contacts);
    const Eigen::MatrixXd monodromy = shooting.monodromy(p.z0, p.omega_b);
    r.branch_floquets.push_back(bright_floquet(monodromy, r.edge.mean_flow, {c.unit_tolerance}));
    r.branch_krein.push_back(
        krein_of(monodromy, parameters, r.branch_floquets.back().trivial_distance, c, r.edge.mean_flow));
  }
  r.bifurcations = branch_bifurcations(branch_samples(r, c.unit_tolerance));
}

// Continues the solved breather in omega_b within the non-resonant window: away from its edge
// (omega_b rising above an edge with h_tilde > 0, falling below one with h_tilde < 0), or towards c.to
// (its last point solved there).
void continue_in_omega_b(const sim::dark::DarkShooting& shooting, const BrightBreatherConfig& c,
                         const BrightBreatherHooks& hooks, BrightBreatherResult& r) {
  std::tie(r.window_low, r.window_high) = non_resonant_window(r.bands, c.omega_b);
  const bool rising = r.edge.nls.h_tilde > 0;
  sim::dark::ContinuationOptions o = continuation_options(c);
  o.direction = rising ? 1.0 : -1.0;
  o.omega_min = rising ? std::max(r.window_low, r.edge.nls.omega) : r.window_low;
  o.omega_max = rising ? r.window_high : std::min(r.window_high, r.edge.nls.omega);
  if (c.to) {
    if (!(*c.to >= o.omega_min && *c.to <= o.omega_max))  // it narrows the window, never crosses the edge
      throw InvalidParameter("to", fmt::format("must lie in [{:.10g}, {:.10g}], the non-resonant window on this side "
                                               "of the band edge {:.10g}, got {:.10g}",
                                               o.omega_min, o.omega_max, r.edge.nls.omega, *c.to));
    o.direction = *c.to > c.omega_b ? 1.0 : -1.0;
    (*c.to > c.omega_b ? o.omega_max : o.omega_min) = *c.to;
    o.land_on_bounds = true;
  }
  r.branch = sim::dark::continue_branch(shooting, r.z0, c.omega_b, o, hooks.on_point);
}

// Continues the breather z0 at `start` of the model parameter `parameter` at fixed omega_b to `end` (the
// last point solved there), on all of Z(0) (sim/dark/parameter_shooting.hpp).
sim::dark::BranchResult continue_in_model_parameter(const BrightBreatherConfig& c, const std::string& parameter,
                                                    double start, double end, const Eigen::VectorXd& z0,
                                                    const BrightBreatherHooks& hooks) {
  const Model& model = *c.model;
  const auto& definitions = model.definition().parameters;
  sim::dark::ParameterShootingSetup setup;
  setup.kernels = c.kernels;
  setup.parameters = sim::lattice_parameters(model);
  for (std::size_t i = 0; i < definitions.size(); ++i)
    if (definitions[i].name == parameter) setup.index = Index(i), setup.range = definitions[i];
  setup.parameters[std::size_t(setup.index)] = start;
  setup.sites = c.sites;
  setup.mean_flow = model.definition().mean_flow;
  setup.omega_b = c.omega_b;
  const sim::dark::ParameterShooting shooting(std::move(setup));
  sim::dark::ContinuationOptions o = continuation_options(c);
  // as dark continue --parameter: ds about a step in the parameter, a chord corrector refreshed below
  // 10x contraction (continuation.hpp)
  o.state_weight = 0;
  o.easy_corrector = 6;
  o.hard_corrector = 10;
  o.chord_contraction = 0.1;
  o.direction = end > start ? 1.0 : -1.0;
  o.omega_min = std::min(start, end);
  o.omega_max = std::max(start, end);
  o.land_on_bounds = true;
  return sim::dark::continue_branch(shooting, z0, start, o, hooks.on_point);
}

// Continues the solved breather in the model parameter c.parameter from its value to c.to.
void continue_in_parameter(const BrightBreatherConfig& c, const BrightBreatherHooks& hooks, BrightBreatherResult& r) {
  const double start = c.model->parameter(c.parameter), end = *c.to;
  r.window_low = std::min(start, end), r.window_high = std::max(start, end);
  r.branch = continue_in_model_parameter(c, c.parameter, start, end, r.z0, hooks);
}

// The anti-continuum start (anti_continuum.hpp): the orbit of the uncoupled lattice (c.coupling = 0)
// at omega_b, continued in the coupling to its value; the last point, or the orbit itself when the
// coupling is 0. Sets r.start_failure (and returns the orbit) when the continuation stops short.
Eigen::VectorXd anti_continuum_start(const BrightBreatherConfig& c, const BrightBreatherHooks& hooks,
                                     BrightBreatherResult& r) {
  const Model& model = *c.model;
  std::vector<double> uncoupled = sim::lattice_parameters(model);
  const auto& definitions = model.definition().parameters;
  for (std::size_t i = 0; i < definitions.size(); ++i)
    if (definitions[i].name == c.coupling) uncoupled[i] = 0;
  const sim::dark::DarkShooting shooting(*c.kernels, uncoupled, c.sites, false, sim::dark::ShootingMode::reversible, {},
                                         sim::dark::model_contact_bonds(*c.kernels, uncoupled, false));
  const sim::bright::AntiContinuumOrbit orbit =
      sim::bright::anti_continuum_orbit(shooting, c.omega_b, c.sites, c.center == "bond", r.edge.theta != 0);
  r.anti_continuum_amplitude = orbit.amplitude;
  // The orbit solves the lattice at coupling 0 only if that parameter uncouples the cells.
  Eigen::VectorXd residual;
  shooting.evaluate(orbit.z0, c.omega_b, residual, nullptr);
  if (const double worst = residual.lpNorm<Eigen::Infinity>(); !(worst <= 1e-8 * std::max(1.0, orbit.amplitude)))
    throw InvalidParameter("coupling", fmt::format("{} = 0 does not uncouple the cells of {}: one oscillator at omega_b = "
                                                   "{} with the others at rest is no orbit there (residual {:.3g}); name "
                                                   "the parameter of the coupling between neighbours",
                                                   c.coupling, model.name(), c.omega_b, worst));
  const double coupling = model.parameter(c.coupling);
  if (coupling == 0) return orbit.z0;
  BrightBreatherConfig steps = c;
  steps.points = 1000;  // the continuation ends at the coupling's value, not at a count of points
  r.anti_continuum_branch = continue_in_model_parameter(steps, c.coupling, 0.0, coupling, orbit.z0, hooks);
  const auto& points = r.anti_continuum_branch.points;
  if (points.empty() || points.back().parameter != coupling) {
    r.start_failure = fmt::format("the anti-continuum orbit (amplitude {:.10g} at {} = 0) continued in {} stopped at {} "
                                  "= {:.10g} before its value {:.10g}: {}",
                                  orbit.amplitude, c.coupling, c.coupling, c.coupling,
                                  points.empty() ? 0.0 : points.back().parameter, coupling,
                                  r.anti_continuum_branch.stop_reason);
    return orbit.z0;
  }
  return points.back().z0;
}

// The continuation the config asks for, then the points kept and their stability.
void continue_breather(const sim::dark::DarkShooting& shooting, const sim::dark::ContactBonds& contacts,
                       const BrightBreatherConfig& c, const BrightBreatherHooks& hooks, BrightBreatherResult& r) {
  const std::vector<double> parameters = sim::lattice_parameters(*c.model);
  if (c.parameter == "omega_b") {
    continue_in_omega_b(shooting, c, hooks, r);
    keep_bright_points(c, [&](const sim::dark::BranchPoint&) { return parameters; }, contacts, r);
    locate_crossings(c, [&](double omega_b, const Eigen::VectorXd& guess) {
      return resolved_breather(shooting, omega_b, guess, c, r.edge.mean_flow);
    }, r);
    return;
  }
  continue_in_parameter(c, hooks, r);
  Index index = 0;
  const auto& definitions = c.model->definition().parameters;
  while (definitions[std::size_t(index)].name != c.parameter) ++index;
  const auto parameters_at = [&](double value) {
    std::vector<double> at = parameters;
    at[std::size_t(index)] = value;
    return at;
  };
  keep_bright_points(c, [&](const sim::dark::BranchPoint& p) { return parameters_at(p.parameter); }, contacts, r);
  // at fixed omega_b, on the lattice at each value of the parameter (as keep_bright_points)
  locate_crossings(c, [&](double value, const Eigen::VectorXd& guess) {
    const sim::dark::DarkShooting at(*c.kernels, parameters_at(value), c.sites, r.edge.mean_flow,
                                     sim::dark::ShootingMode::reversible, {}, contacts);
    return resolved_breather(at, c.omega_b, guess, c, r.edge.mean_flow);
  }, r);
}

// Floquet multipliers of the solved breather, the perturbation (`unstable`: along the eigenvector of
// the largest multiplier, refused when none is unstable) and the evolution over c.periods periods.
void evolve_breather(const sim::dark::DarkShooting& shooting, const BrightBreatherConfig& c, BrightBreatherResult& r) {
  const Eigen::MatrixXd monodromy = shooting.monodromy(r.z0, c.omega_b);
  r.floquet = bright_floquet(monodromy, r.edge.mean_flow, {c.unit_tolerance});
  r.predicted_growth_rate = std::log(r.floquet->max_nontrivial_modulus) * c.omega_b / (2 * std::numbers::pi);
  if (c.perturb == "unstable" && r.floquet->stable)
    throw InvalidParameter("perturb", fmt::format("unstable needs an unstable Floquet multiplier, and the breather at "
                                                  "omega_b = {} is stable (max |lambda| = {:.9f} besides the trivial "
                                                  "+1 ones): use random or none",
                                                  c.omega_b, r.floquet->max_nontrivial_modulus));
  if (c.perturb == "unstable") r.perturbation = sim::dark::unstable_perturbation(monodromy, c.perturb_size);
  else if (c.perturb == "random") r.perturbation = sim::dark::random_perturbation(r.z0.size(), c.perturb_size, c.seed);
  r.evolution = evolve_bright_breather(shooting, r.z0, c.omega_b, c.periods, r.perturbation.vector);
}

}  // namespace

BrightBreatherResult run(const BrightBreatherConfig& c, const BrightBreatherHooks& hooks) {
  const auto start = std::chrono::steady_clock::now();
  BrightBreatherResult r;
  r.config = c;
  const Model& model = *c.model;
  r.bands = linear_bands(model);
  double top = 0;
  for (const auto& band : r.bands) top = std::max(top, band.highest);
  r.harmonics_checked = std::max<Index>(1, Index(std::floor(top / c.omega_b)));
  const std::optional<Index> branch = c.branch.empty() ? std::nullopt : std::optional(model.branch(c.branch));
  const FocusingEdge edge = focusing_edge(model, branch, c.omega_b);
  const sim::ModelBrightAnsatz ansatz = bright_ansatz(model, *c.kernels, edge, c.omega_b, parse_dark_center(c.center));
  const bool mean_flow = model.definition().mean_flow;
  const std::vector<double> parameters = sim::lattice_parameters(model);
  const sim::dark::ContactBonds contacts = sim::dark::model_contact_bonds(*c.kernels, parameters, mean_flow);
  r.edge = {model.definition().branch_names.at(std::size_t(edge.branch)), edge.theta, edge.nls, 2 * ansatz.M2(),
            ansatz.inverse_width(), mean_flow, c.kernels->fields, {}, {}, {}};
  lattice_variable_names(r.edge.mean_flow, r.edge.fields, r.edge.variables, r.edge.variable_meanings);
  for (const auto& bond : contacts) r.edge.one_sided_contacts.push_back(bond.name);
  const sim::dark::DarkShooting shooting(*c.kernels, parameters, c.sites, mean_flow, sim::dark::ShootingMode::reversible,
                                         {}, contacts);
  r.seed = c.start == "anti-continuum" ? anti_continuum_start(c, hooks, r)
                                       : bright_seed(ansatz, mean_flow, c.kernels->fields, c.sites);
  const BrightProfileOptions profile_options = bright_profile_options(c);
  r.seed_profile = inspect_bright_profile(r.seed, c.sites, profile_options);
  if (!r.start_failure.empty()) {
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return r;
  }
  BreatherSolverOptions solver = c.krylov;
  // the continuation's Jacobian and the evolution's monodromy are dense
  if (c.step == BrightStep::branch || c.step == BrightStep::evolve) solver.solver = "dense";
  r.newton = solve_breather(shooting, r.seed, c.omega_b, newton_options(c, hooks), solver, r.krylov);
  if (r.newton.converged) {
    r.z0 = r.newton.q;
    r.profile = inspect_bright_profile(r.z0, c.sites, profile_options);
    r.seed_difference = relative_profile_difference(r.z0, r.seed);
    r.rejected = r.profile.reason;
    if (r.rejected.empty()) r.rejected = fundamental_period_reason(shooting.orbit(), r.z0, c.omega_b);
    if (r.rejected.empty() && c.step == BrightStep::floquet && r.krylov)
      windowed_floquet(shooting, {c.kernels, parameters, mean_flow, contacts}, r.z0, c.omega_b, c.krylov,
                       c.unit_tolerance, *r.krylov);
    else if (r.rejected.empty() && c.step == BrightStep::floquet) {
      const Eigen::MatrixXd monodromy = shooting.monodromy(r.z0, c.omega_b);
      r.floquet = bright_floquet(monodromy, mean_flow, {c.unit_tolerance});
      r.krein = krein_of(monodromy, parameters, r.floquet->trivial_distance, c, mean_flow);
    }
    if (r.rejected.empty() && c.step == BrightStep::branch) continue_breather(shooting, contacts, c, hooks, r);
    if (r.rejected.empty() && c.step == BrightStep::evolve) evolve_breather(shooting, c, r);
  }
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return r;
}

std::optional<std::string> failure(const BrightBreatherResult& r) {
  if (!r.start_failure.empty()) return r.start_failure;
  if (!r.newton.converged) return sim::dark::newton_failure_message(r.newton, r.config.omega_b);
  if (!r.rejected.empty())
    return fmt::format("Newton converged at omega_b = {} to no bright breather: {}", r.config.omega_b, r.rejected);
  return std::nullopt;
}

}  // namespace lrchain::jobs::bright_breather

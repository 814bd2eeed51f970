// run(DarkConfig): Newton from the seed on the resonant chain's shooting (eq:xy_app) or a model's,
// then the step asked for: measures and Floquet multipliers, the branch, or the evolution.
#include <cmath>
#include <numbers>
#include <optional>

#include <fmt/format.h>

#include "../breather_outputs.hpp"
#include "dark_steps.hpp"
#include "lrchain/ansatz/dark_breather.hpp"
#include "lrchain/dispersion.hpp"
#include "lrchain/jobs/dark_job.hpp"
#include "lrchain/sim/dark/dark_ansatz.hpp"
#include "lrchain/errors.hpp"
#include "lrchain/sim/dark/dark_shape.hpp"
#include "lrchain/sim/dark/floquet.hpp"
#include "lrchain/sim/dark/perturbation.hpp"
#include "lrchain/sim/dark/lattice_reflection.hpp"
#include "lrchain/sim/dark/parameter_shooting.hpp"
#include "lrchain/sim/dark/shooting.hpp"
#include "lrchain/sim/dark/symmetric_shooting.hpp"
#include "lrchain/sim/model_lattice_bloch.hpp"

namespace lrchain::jobs::dark {

using namespace lrchain::sim::dark;

namespace {

// perturb unstable needs an instability: on a stable breather (Floquet classification, symmetry
// multipliers at +1 excluded) the leading eigenvector is a neutral mode and nothing would grow, so it
// is refused naming perturb.
DarkPerturbation unstable_perturbation_of(const Eigen::MatrixXd& monodromy, double size) {
  const FloquetResult floquet = floquet_from_monodromy(monodromy);
  if (floquet.kind() == "stable")
    throw InvalidParameter("perturb", fmt::format("unstable needs an unstable breather, this one is stable (no Floquet "
                                                  "multiplier off the unit circle, max|lambda| = {:.8g}): use perturb random",
                                                  floquet.max_modulus));
  return unstable_perturbation(monodromy, size);
}

// The continuation's options from the config. A model's arclength weighs the unknowns so that ds is a
// step of about ds in the parameter, its chord corrector refreshes below 10x contraction
// (continuation.hpp); the resonant chain keeps the plain arclength of its figures.
ContinuationOptions continuation_options(const DarkConfig& c, const DarkRunHooks& hooks, bool model_file) {
  ContinuationOptions o;
  o.stop = hooks.stop;
  o.max_points = c.points;
  o.ds = c.ds;
  o.tolerance = c.tolerance;
  o.floquet = c.branch_floquet;
  if (model_file) {
    o.state_weight = 0;
    o.easy_corrector = 6;
    o.hard_corrector = 10;
    o.chord_contraction = 0.1;
  }
  return o;
}

sim::dark::NewtonOptions newton_options(const DarkConfig& c, const DarkRunHooks& hooks) {
  NewtonOptions o;
  o.tolerance = c.tolerance;
  o.max_iterations = c.max_iterations;
  o.progress = hooks.newton_progress;
  return o;
}

// The resonant chain (Params): seed eq:xy_app, reversible or full-period shooting (Sec. 5.3).
void run_chain(const DarkConfig& c, const DarkRunHooks& hooks, const ContactIntegrationOptions& integration,
               DarkResult& r) {
  const std::string branch = c.branch.empty() ? "optical" : c.branch;
  const DarkCenter center = parse_dark_center(c.center);
  const DarkBreatherAnsatz ansatz = make_dark_breather_ansatz(c.params, parse_branch(branch), c.omega_b);
  r.edge.branch = branch;
  r.edge.theta = std::numbers::pi;
  r.edge.omega = ansatz.omega;
  r.edge.variables = {"x", "y"};
  const ResonantChainShooting shooting(c.params, *c.sites, center, parse_shooting_mode(c.mode), integration);
  r.seed = resonant_chain_dark_seed(ansatz, center, *c.sites);
  r.newton = newton_solve(shooting, shooting.unknowns_from_z(r.seed), c.omega_b, newton_options(c, hooks));
  if (!r.newton.converged) return;
  r.z0 = shooting.z_from_unknowns(r.newton.q);
  const double period = 2 * std::numbers::pi / c.omega_b;
  switch (c.step) {
    case DarkStep::branch:
      continue_from(shooting, r.newton.q, c, hooks, r);
      return;
    case DarkStep::evolve: {
      if (c.perturb == "unstable") {  // the full-period monodromy's leading eigenvector
        Eigen::VectorXd residual;
        Eigen::MatrixXd jacobian, monodromy;
        const ResonantChainShooting full(c.params, *c.sites, center, ShootingMode::full, shooting.integration());
        full.evaluate(full.unknowns_from_z(r.z0), c.omega_b, residual, &jacobian, &monodromy);
        r.perturbation = unstable_perturbation_of(monodromy, c.perturb_size);
      } else if (c.perturb == "random") {
        r.perturbation = random_perturbation(r.z0.size(), c.perturb_size, c.seed);
      }
      r.evolution = evolve_dark_breather(c.params, r.z0, c.omega_b, c.t_end, c.samples, shooting.integration(), hooks.stop,
                                       hooks.evolution_progress, r.perturbation.vector);
      return;
    }
    case DarkStep::solve:
    case DarkStep::floquet:
      break;
  }
  r.measures = measure_dark_breather(c.params, r.z0, c.omega_b, shooting.integration());
  if (c.step == DarkStep::floquet) {
    Eigen::VectorXd residual;
    Eigen::MatrixXd jacobian, propagator;
    if (c.full_monodromy || shooting.mode() == ShootingMode::full) {
      const ResonantChainShooting full(c.params, *c.sites, center, ShootingMode::full, shooting.integration());
      full.evaluate(full.unknowns_from_z(r.z0), c.omega_b, residual, &jacobian, &propagator);
      r.floquet = floquet_from_monodromy(propagator);
      r.monodromy = "full period";
    } else {
      shooting.evaluate(r.newton.q, c.omega_b, residual, &jacobian, &propagator);
      r.floquet = floquet_reversible(shooting, propagator);
      r.monodromy = "reversible reduction";
    }
  }
  if (!c.out.empty())  // the profile's Z(T_b)
    r.z_period = dark_breather_evolution(c.params, r.z0, period, 1, shooting.integration()).back();
}

// Continues a model's breather (unknowns q0 of its family, or all of Z(0)) in the model parameter
// c.parameter at fixed omega_b, from its value towards c.to, the last point solved at c.to.
void continue_in_parameter(const DarkConfig& c, const DarkRunHooks& hooks, const Eigen::VectorXd& q0,
                           const std::optional<LatticeReflection>& reflection, DarkResult& r) {
  const Model& model = *c.model;
  const auto& parameters = model.definition().parameters;
  ParameterShootingSetup setup;
  setup.kernels = c.kernels;
  setup.parameters = sim::lattice_parameters(model);
  for (std::size_t i = 0; i < parameters.size(); ++i)
    if (parameters[i].name == c.parameter) setup.index = Index(i), setup.range = parameters[i];
  setup.sites = *c.sites;
  setup.mean_flow = r.edge.mean_flow;
  setup.mode = parse_shooting_mode(c.mode);
  if (hooks.stop) setup.integration.stop = hooks.stop;
  setup.reflection = reflection;
  setup.omega_b = c.omega_b;
  const ParameterShooting shooting(std::move(setup));
  const double start = model.parameter(c.parameter), end = *c.to;
  ContinuationOptions o = continuation_options(c, hooks, true);
  o.direction = end > start ? 1.0 : -1.0;
  o.omega_min = std::min(start, end);
  o.omega_max = std::max(start, end);
  o.land_on_bounds = true;
  r.branch = continue_branch(shooting, q0, start, o, hooks.on_point);
}

// How closely a solved breather must be symmetric to be continued in a reflection family (relative to
// its largest entry): Newton leaves it off along the weakly pinned translation direction (the
// resonant_chain_polynomial pair at omega_b = 2.01 on 60 sites: 2.4e-6 with a residual of 1e-12); the
// family's Newton then polishes it, or reports that the solution is not in the family.
constexpr double kSolvedSymmetryTolerance = 1e-4;

// The positions Z(T_b/2) of the orbit from [Z(0), 0]: the solved breather's half-period image, asked for
// its reflection when the seed's was not found (a pair of dips at a theta = 0 edge is symmetric only up
// to its tails, which the ring's periodic closure changes; the solution is symmetric to round-off).
Eigen::VectorXd state_at_half_period(const DarkShooting& shooting, const Eigen::VectorXd& z0, double omega_b) {
  const Index positions = shooting.orbit().positions();
  std::vector<double> state(std::size_t(2 * positions), 0.0);
  std::copy(z0.data(), z0.data() + positions, state.begin());
  shooting.orbit().integrate(state, 0.0, std::numbers::pi / omega_b);
  return Eigen::Map<const Eigen::VectorXd>(state.data(), positions);
}

// Continues a model's solved breather r.z0 within its reflection family (symmetric_shooting.hpp), so
// that the steps cannot slide along the translation mode; without a reflection symmetry, on all of Z(0).
void continue_in_family(const DarkShooting& shooting, const DarkAnsatz& ansatz, const DarkConfig& c,
                        const DarkRunHooks& hooks, DarkResult& r) {
  const DarkCenter center = parse_dark_center(c.center);
  const double centre = dark_seed_centre(ansatz, center, *c.sites);
  std::optional<LatticeReflection> reflection = find_dark_reflection(
      shooting.orbit().lattice(), centre, r.seed, dark_seed_half_period(ansatz, center, *c.sites));
  if (!reflection)
    reflection = find_dark_reflection(shooting.orbit().lattice(), centre, r.z0, state_at_half_period(shooting, r.z0, c.omega_b),
                                      kSolvedSymmetryTolerance);
  if (!reflection) {
    if (c.parameter != "omega_b") continue_in_parameter(c, hooks, r.z0, std::nullopt, r);
    else continue_from(shooting, r.z0, c, hooks, r);
    return;
  }
  r.symmetry = reflection->description;
  const SymmetricDarkShooting family(shooting, *reflection);
  if (c.parameter != "omega_b") {
    continue_in_parameter(c, hooks, family.unknowns_from_z(r.z0), reflection, r);
    return;
  }
  NewtonOptions polish = newton_options(c, hooks);
  polish.progress = {};
  // Newton's solution is symmetric to round-off: a step or two in the family's unknowns.
  const NewtonResult start = newton_solve(family, family.unknowns_from_z(r.z0), c.omega_b, polish);
  if (!start.converged) {
    r.newton.converged = false;
    r.newton.failure = "the solution is not in its reflection family (" + reflection->description + "): " + start.failure;
    return;
  }
  r.z0 = family.z_from_unknowns(start.q);
  continue_from(family, start.q, c, hooks, r);
}

// A model file on its generated lattice kernels: the seed at its defocusing edge, full-period shooting.
void run_model(const DarkConfig& c, const DarkRunHooks& hooks, const ContactIntegrationOptions& integration,
               DarkResult& r) {
  const Model& model = *c.model;
  const std::optional<Index> given = c.branch.empty() ? std::nullopt : std::optional(model.branch(c.branch));
  const DarkAnsatz ansatz = make_dark_ansatz(model, *c.kernels, defocusing_edge(model, given), c.omega_b);
  const ContactBonds contacts = model_contact_bonds(*c.kernels, sim::lattice_parameters(model), ansatz.mean_flow);
  r.edge = {model.definition().branch_names.at(std::size_t(ansatz.branch)), ansatz.theta, ansatz.omega,
            ansatz.curvature, ansatz.h_tilde, ansatz.lambda, ansatz.mean_flow, c.kernels->fields, {}, {}, {}};
  lattice_variable_names(r.edge.mean_flow, r.edge.fields, r.edge.variables, r.edge.variable_meanings);
  for (const auto& bond : contacts) r.edge.one_sided_contacts.push_back(bond.name);
  const DarkShooting shooting(*c.kernels, sim::lattice_parameters(model), *c.sites, ansatz.mean_flow,
                                   parse_shooting_mode(c.mode), integration, contacts);
  r.seed = dark_seed(ansatz, parse_dark_center(c.center), *c.sites);
  BreatherSolverOptions solver = c.krylov;
  if (c.step == DarkStep::branch || shooting.mode() == ShootingMode::full) solver.solver = "dense";
  r.newton = solve_breather(shooting, r.seed, c.omega_b, newton_options(c, hooks), solver, r.krylov);
  if (!r.newton.converged) return;
  // A zero of the shooting map is any periodic orbit: keep it only if it is a dark breather.
  if (const std::string shape = dark_shape_failure(ansatz, parse_dark_center(c.center), *c.sites, r.newton.q);
      !shape.empty()) {
    r.newton.converged = false;
    r.newton.failure = "it converged to a state that is not a dark breather (" + shape + ")";
    return;
  }
  r.z0 = r.newton.q;
  if (c.step == DarkStep::branch) {  // the start's contact changes are its branch point's
    continue_in_family(shooting, ansatz, c, hooks, r);
    return;
  }
  r.contact_changes_per_period = shooting.contact_changes_per_period(r.z0, c.omega_b);
  if (c.step == DarkStep::evolve) {
    if (c.perturb == "unstable")
      r.perturbation = unstable_perturbation_of(shooting.monodromy(r.z0, c.omega_b), c.perturb_size);
    else if (c.perturb == "random")
      r.perturbation = random_perturbation(r.z0.size(), c.perturb_size, c.seed);
    r.evolution = evolve_dark_orbit(shooting.advance(), r.z0, *c.sites, c.omega_b, c.t_end, c.samples, hooks.stop,
                                    hooks.evolution_progress, r.perturbation.vector);
    return;
  }
  shooting.measure(r.z0, c.omega_b, r.measures);
  if (c.step == DarkStep::floquet && r.krylov && ansatz.theta != 0 && use_dark_window(c.krylov, *c.sites)) {
    windowed_dark_floquet(shooting, {c.kernels, sim::lattice_parameters(model), ansatz.mean_flow, contacts}, r.z0,
                          c.omega_b, c.krylov, c.tolerance, *r.krylov);
  } else if (c.step == DarkStep::floquet && r.krylov) {  // Arnoldi (and a pair at theta = 0)
    krylov_floquet(shooting, r.z0, c.omega_b, c.krylov, *r.krylov);
  } else if (c.step == DarkStep::floquet) {
    r.floquet = floquet_from_monodromy(shooting.monodromy(r.z0, c.omega_b));
    r.monodromy = "full period";
  }
  if (!c.out.empty()) {  // the profile's Z(T_b)
    std::vector<double> state(2 * std::size_t(r.z0.size()), 0.0);
    std::copy(r.z0.data(), r.z0.data() + r.z0.size(), state.begin());
    shooting.orbit().integrate(state, 0.0, 2 * std::numbers::pi / c.omega_b);
    r.z_period = Eigen::Map<const Eigen::VectorXd>(state.data(), r.z0.size());
  }
}

}  // namespace

// Continues a solved breather q0 away from the band edge: into the gap (omega_b falling) below an
// edge, rising above one (a model edge with h > 0), within [omega_min, omega_max].
void continue_from(const DarkShootingProblem& shooting, const Eigen::VectorXd& q0, const DarkConfig& c,
                   const DarkRunHooks& hooks, DarkResult& r) {
  const double edge = r.edge.omega;
  ContinuationOptions o = continuation_options(c, hooks, r.model_file());
  const bool above = c.omega_b > edge;
  o.direction = above ? 1.0 : -1.0;
  o.omega_min = above ? std::max(c.omega_min, edge) : c.omega_min;
  o.omega_max = c.omega_max > 0 ? c.omega_max : above ? 1e300 : edge;
  if (c.to) {  // the direction and the end of the range, its last point solved there
    if (!(*c.to >= o.omega_min && *c.to <= o.omega_max))  // it narrows the window, never widens it
      throw InvalidParameter("to", fmt::format("must lie in [{:.10g}, {:.10g}], between omega_min, omega_max and the "
                                               "band edge {:.10g} that the branch cannot cross, got {:.10g}",
                                               o.omega_min, o.omega_max, edge, *c.to));
    o.direction = *c.to > c.omega_b ? 1.0 : -1.0;
    (*c.to > c.omega_b ? o.omega_max : o.omega_min) = *c.to;
    o.land_on_bounds = true;
  }
  r.branch = continue_branch(shooting, q0, c.omega_b, o, hooks.on_point);
}

DarkResult run(const DarkConfig& config, const DarkRunHooks& hooks) {
  DarkResult r;
  r.config = config;
  r.config.sites = dark_sites(config);  // the result says how many
  const DarkConfig& c = r.config;
  ContactIntegrationOptions integration;
  // A branch keeps its points when a signal ends it inside an integration (continue_branch).
  if (hooks.stop_integrations || c.step == DarkStep::branch) integration.stop = hooks.stop;
  if (c.model) run_model(c, hooks, integration, r);
  else run_chain(c, hooks, integration, r);
  return r;
}

}  // namespace lrchain::jobs::dark

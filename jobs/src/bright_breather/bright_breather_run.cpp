// run(BrightBreatherConfig): the bands and harmonics checked, the focusing edge and its NLS seed,
// Newton on the time-reversible shooting shared with the dark breathers, the localization check,
// and (floquet) the multipliers of the full-period monodromy (bright_breather_job.hpp).
#include <chrono>
#include <cmath>
#include <tuple>

#include <fmt/format.h>

#include "../breather_outputs.hpp"
#include "lrchain/jobs/bright_breather_job.hpp"
#include "lrchain/sim/bright/bright_seed.hpp"
#include "lrchain/sim/dark/contact_bonds.hpp"
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

// The kept branch points as the bifurcation detector sees them: arclength |d(Z(0), omega_b)| summed
// from the first point, slope, norm and (with Floquet) the real multipliers beyond +1 and -1.
std::vector<BranchSample> branch_samples(const BrightBreatherResult& r, double unit_tolerance) {
  std::vector<BranchSample> samples;
  double s = 0;
  for (std::size_t k = 0; k < r.branch_profiles.size(); ++k) {
    const sim::dark::BranchPoint& p = r.branch.points[k];
    if (k > 0) {
      const sim::dark::BranchPoint& q = r.branch.points[k - 1];
      s += std::sqrt((p.z0 - q.z0).squaredNorm() + (p.omega_b - q.omega_b) * (p.omega_b - q.omega_b));
    }
    BranchSample sample{s, p.omega_b, p.tangent_omega, r.branch_profiles[k].norm_squared, std::nullopt, std::nullopt,
                        std::nullopt};
    if (k < r.branch_floquets.size()) {
      sample.real_unstable = real_multipliers_beyond(r.branch_floquets[k], +1, unit_tolerance);
      sample.period_doubling = real_multipliers_beyond(r.branch_floquets[k], -1, unit_tolerance);
      sample.oscillatory = r.branch_floquets[k].multipliers.oscillatory;
    }
    samples.push_back(sample);
  }
  return samples;
}

// Continues the solved breather away from its edge (omega_b rising above an edge with h_tilde > 0,
// falling below one with h_tilde < 0) within the non-resonant window; each point's profile checked
// and (branch_floquet) its multipliers; the branch ends before its first point that is no breather.
void continue_away_from_edge(const sim::dark::DarkShooting& shooting, const BrightBreatherConfig& c,
                             const BrightBreatherHooks& hooks, BrightBreatherResult& r) {
  std::tie(r.window_low, r.window_high) = non_resonant_window(r.bands, c.omega_b);
  const bool rising = r.edge.nls.h_tilde > 0;
  sim::dark::ContinuationOptions o;
  o.ds = c.ds;
  o.max_points = c.points;
  o.tolerance = c.tolerance;
  o.floquet = false;  // the bright Floquet analysis below, with the trivial multipliers removed
  o.direction = rising ? 1.0 : -1.0;
  o.omega_min = rising ? std::max(r.window_low, r.edge.nls.omega) : r.window_low;
  o.omega_max = rising ? r.window_high : std::min(r.window_high, r.edge.nls.omega);
  const BrightProfileOptions profile_options{c.tail_tolerance};
  r.branch = sim::dark::continue_branch(shooting, r.z0, c.omega_b, o, hooks.on_point);
  const Eigen::VectorXd masses = position_masses(*c.kernels, sim::lattice_parameters(*c.model), c.sites);
  for (std::size_t k = 0; k < r.branch.points.size(); ++k) {
    const sim::dark::BranchPoint& p = r.branch.points[k];
    BrightProfile profile = inspect_bright_profile(p.z0, c.sites, profile_options);
    if (!profile.localized) {
      r.branch.stop_reason = fmt::format("the branch point at omega_b = {:.6f} is no bright breather: {}", p.omega_b,
                                         profile.reason);
      r.branch.points.resize(k);
      r.branch.turning_points.clear();  // those of the points kept: d omega_b / ds changing sign
      for (std::size_t j = 1; j < k; ++j)
        if ((r.branch.points[j].tangent_omega > 0) != (r.branch.points[j - 1].tangent_omega > 0))
          r.branch.turning_points.push_back(r.branch.points[j].omega_b);
      break;
    }
    r.branch_profiles.push_back(std::move(profile));
    if (!c.branch_floquet) continue;
    const Eigen::MatrixXd monodromy = shooting.monodromy(p.z0, p.omega_b);
    r.branch_floquets.push_back(bright_floquet(monodromy, r.edge.mean_flow, {c.unit_tolerance}));
    if (!r.edge.mean_flow)
      r.branch_krein.push_back(
          krein_signatures(monodromy, masses, c.unit_tolerance, r.branch_floquets.back().trivial_distance));
  }
  r.bifurcations = branch_bifurcations(branch_samples(r, c.unit_tolerance));
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
  r.seed = bright_seed(ansatz, mean_flow, c.kernels->fields, c.sites);
  const BrightProfileOptions profile_options{c.tail_tolerance};
  r.seed_profile = inspect_bright_profile(r.seed, c.sites, profile_options);
  BreatherSolverOptions solver = c.krylov;
  if (c.step == BrightStep::branch) solver.solver = "dense";  // the continuation's Jacobian is dense
  r.newton = solve_breather(shooting, r.seed, c.omega_b, newton_options(c, hooks), solver, r.krylov);
  if (r.newton.converged) {
    r.z0 = r.newton.q;
    r.profile = inspect_bright_profile(r.z0, c.sites, profile_options);
    r.seed_difference = relative_profile_difference(r.z0, r.seed);
    r.rejected = r.profile.reason;
    if (r.rejected.empty() && c.step == BrightStep::floquet && r.krylov)
      krylov_floquet(shooting, r.z0, c.omega_b, c.krylov, *r.krylov);
    else if (r.rejected.empty() && c.step == BrightStep::floquet)
      r.floquet = bright_floquet(shooting.monodromy(r.z0, c.omega_b), mean_flow, {c.unit_tolerance});
    if (r.rejected.empty() && c.step == BrightStep::branch) continue_away_from_edge(shooting, c, hooks, r);
  }
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return r;
}

std::optional<std::string> failure(const BrightBreatherResult& r) {
  if (!r.newton.converged) return sim::dark::newton_failure_message(r.newton, r.config.omega_b);
  if (!r.rejected.empty())
    return fmt::format("Newton converged at omega_b = {} to no bright breather: {}", r.config.omega_b, r.rejected);
  return std::nullopt;
}

}  // namespace lrchain::jobs::bright_breather

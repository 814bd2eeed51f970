// Band edge and seed of a dark breather of any model file (dark_ansatz.hpp).
#include "lrchain/sim/dark/dark_ansatz.hpp"

#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include <Eigen/Eigenvalues>

#include "lrchain/errors.hpp"
#include "lrchain/sim/model_lattice.hpp"
#include "lrchain/sim/model_lattice_bloch.hpp"

namespace lrchain::sim::dark {

// The NLS regime at the edge theta of `branch` (singular where there are no coefficients, or h_tilde
// diverges there) and its text, e.g. "focusing (omega'' h_tilde = -0.0312)".
std::string band_edge_regime(const Model& model, Index branch, double theta, Regime& regime) {
  regime = Regime::singular;
  try {
    const NlsCoefficients c = coefficients_from_evaluators(model, branch, theta);
    if (c.regime == Regime::singular || !std::isfinite(c.curvature * c.h_tilde)) return "singular coefficients";
    // An NLS coefficient that diverges at the edge (the diatomic chain's h at theta = pi) is finite
    // but huge at the rounded edge: the edge is singular when h_tilde there is not the limit of its
    // values just inside the band (theta 1e-4 away: a smooth h_tilde changes by O(1e-8) relatively).
    const double inside = theta == 0 ? 1e-4 : theta - 1e-4;
    const NlsCoefficients near = coefficients_from_evaluators(model, branch, inside);
    if (!(std::abs(c.h_tilde - near.h_tilde) <= 1e-3 * std::abs(near.h_tilde) + 1e-12))
      return fmt::format("singular coefficients (h_tilde = {:.4g} at the edge, {:.4g} at theta = {:.6g})", c.h_tilde,
                         near.h_tilde, inside);
    regime = c.regime;
    return fmt::format("{} (omega'' h_tilde = {:.4g})", to_string(c.regime), c.curvature * c.h_tilde);
  } catch (const InvalidParameter&) {
    return "no real positive frequency";
  }
}

namespace {
// The Bloch vector (K_0 = 1) of frequency omega at theta = 0 from the generated Jacobian at rest:
// D_{gf} = (J 1_f)_g, D K = -omega^2 K. (bloch_mode needs every branch to have a positive
// frequency, and an acoustic branch has omega = 0 at theta = 0.)
std::vector<double> uniform_kernel(const Model& model, const lrchain_lattice_kernels& kernels, double omega) {
  constexpr std::size_t sites = 16;
  const CompiledLattice ring(kernels, lattice_parameters(model), sites, true, LatticeForm::displacement);
  const std::size_t fields = ring.fields();
  const std::vector<double> rest(ring.positions(), 0.0);
  std::vector<double> pattern(ring.positions()), response(ring.positions());
  Eigen::MatrixXd D(fields, fields);
  for (std::size_t f = 0; f < fields; ++f) {
    std::fill(pattern.begin(), pattern.end(), 0.0);
    std::fill(pattern.begin() + std::ptrdiff_t(f * sites), pattern.begin() + std::ptrdiff_t((f + 1) * sites), 1.0);
    ring.jacobian_action(rest.data(), pattern.data(), response.data());
    for (std::size_t g = 0; g < fields; ++g) D(Eigen::Index(g), Eigen::Index(f)) = response[g * sites];
  }
  Eigen::EigenSolver<Eigen::MatrixXd> solver(D);
  Eigen::Index best = 0;
  for (Eigen::Index i = 1; i < D.rows(); ++i)
    if (std::abs(solver.eigenvalues()(i) + omega * omega) < std::abs(solver.eigenvalues()(best) + omega * omega)) best = i;
  if (!(std::abs(solver.eigenvalues()(best) + omega * omega) <= 1e-9 * omega * omega))
    throw NumericalFailure(fmt::format("{}: the lattice code has no mode of frequency {:.12g} at theta = 0 (the coefficient "
                                       "evaluators' omega)", model.name(), omega));
  const Eigen::VectorXcd v = solver.eigenvectors().col(best);
  if (std::abs(v(0)) <= 1e-10 * v.cwiseAbs().maxCoeff())
    throw InvalidParameter("branch", fmt::format("{}: the first field is at rest in the theta = 0 mode", model.name()));
  std::vector<double> kernel;
  for (Eigen::Index f = 0; f < v.size(); ++f) kernel.push_back((v(f) / v(0)).real());
  return kernel;
}

}  // namespace

DefocusingEdge defocusing_edge(const Model& model, std::optional<Index> branch) {
  const auto& names = model.definition().branch_names;
  std::string checked;
  for (Index b = 0; b < static_cast<Index>(names.size()); ++b) {
    if (branch && *branch != b) continue;
    for (const double theta : {std::numbers::pi, 0.0}) {
      Regime found = Regime::singular;
      const std::string regime = band_edge_regime(model, b, theta, found);
      if (found == Regime::defocusing) return {b, theta};
      checked += fmt::format("{}{} at theta = {}: {}", checked.empty() ? "" : "; ", names[static_cast<std::size_t>(b)], theta == 0 ? "0" : "pi",
                             regime);
    }
  }
  throw InvalidParameter("branch", fmt::format("{} has no defocusing band edge for dark breathers (edges checked: {})",
                                               model.name(), checked));
}

DarkAnsatz make_dark_ansatz(const Model& model, const lrchain_lattice_kernels& kernels,
                                       const DefocusingEdge& edge, double omega_b) {
  const Index branch = edge.branch;
  const NlsCoefficients c = coefficients_from_evaluators(model, branch, edge.theta);
  const std::string where = fmt::format("the theta = {} edge of {} branch {}", edge.theta == 0 ? "0" : "pi",
                                        model.name(), model.definition().branch_names.at(static_cast<std::size_t>(branch)));
  if (c.regime != Regime::defocusing) throw InvalidParameter("branch", where + " is not defocusing");
  // With the far-field mean strain fixed to zero (the shooting's C_x row; on-site models have no mean
  // strain) the background plane wave of NLS amplitude A (carrier 2 A cos) has
  // omega_b - omega = h A^2, while h_tilde = h - lambda beta sets the dip (eq:defocus_app with
  // f = lambda mu/h_tilde, as eq:Ftau does for the resonant chain): a dark breather exists only on the
  // side where (omega_b - omega) h > 0.
  const double detuning = omega_b - c.omega;
  if (!(std::isfinite(c.h) && c.h != 0.0))
    throw InvalidParameter("branch", fmt::format("{} has no dark breather: h = {:.6g} there, so the background's "
                                                 "frequency omega + h A^2 does not move off the edge",
                                                 where, c.h));
  if (!(std::isfinite(omega_b) && omega_b > 0.0 && detuning / c.h > 0.0))
    throw InvalidParameter("omega_b", fmt::format("must lie {} omega = {:.10g}, {} (the side where (omega_b - omega) "
                                                  "h > 0, h = {:.6g}: the background's frequency omega + h A^2 with "
                                                  "the far-field mean strain fixed to zero{})",
                                                  c.h < 0 ? "below" : "above", c.omega, where, c.h,
                                                  c.h * c.h_tilde < 0 ? fmt::format("; h_tilde = {:.6g} only sets "
                                                                                    "the dip's width", c.h_tilde)
                                                                      : std::string()));
  DarkAnsatz a;
  a.branch = branch;
  a.theta = edge.theta;
  a.omega_b = omega_b;
  a.omega = c.omega;
  a.curvature = c.curvature;
  a.h = c.h;
  a.h_tilde = c.h_tilde;
  a.mean_flow = model.definition().mean_flow;
  a.lambda = a.mean_flow ? c.lambda : 0.0;
  a.amplitude = std::sqrt(detuning / c.h);                                 // omega_b - omega = h A^2
  a.inverse_width = std::sqrt(c.h_tilde * a.amplitude * a.amplitude / c.curvature);  // eta^2 = -mu/omega'' = h_tilde A^2/omega''
  a.mean_factor = a.mean_flow ? -c.lambda * std::sqrt(c.curvature * c.h_tilde) / std::abs(c.h_tilde) : 0.0;
  if (edge.theta == 0)
    a.kernel = uniform_kernel(model, kernels, c.omega);
  else
    for (const auto& k : bloch_mode(model, kernels, branch, edge.theta).kernel) a.kernel.push_back(k.real());
  return a;
}

void check_dark_sites(const DarkAnsatz& a, Index sites) {
  const bool pi_edge = a.theta != 0;
  if (sites < 9 || (sites % 2 == 1) != pi_edge)
    throw InvalidParameter("sites", pi_edge ? "must be an odd integer >= 9 at a theta = pi edge (a staggered dark "
                                              "breather fits periodic ends only on an odd number of sites)"
                                            : "must be an even integer >= 10 at a theta = 0 edge (a pair of dark "
                                              "breathers half a ring apart)");
}

// u_f[n] at t = 0 (theta = pi: one breather; theta = 0: the pair), in the lattice's variables.
Eigen::VectorXd dark_seed(const DarkAnsatz& a, DarkCenter center, Index sites) {
  check_dark_sites(a, sites);
  const double n0 = dark_center_n0(center);
  const Index half = a.theta != 0 ? (sites - 1) / 2 : 0;
  const std::size_t fields = a.kernel.size();
  const double n1 = 0.25 * static_cast<double>(sites) + n0, n2 = n1 + 0.5 * static_cast<double>(sites);
  auto u = [&](std::size_t f, Index n) {
    if (a.theta == 0) {
      const double t1 = std::tanh(a.inverse_width * (static_cast<double>(n) - n1)),
                 t2 = std::tanh(a.inverse_width * (static_cast<double>(n) - n2));
      return a.amplitude * (a.mean_factor * (t1 + t2) - 2.0 * a.kernel[f] * t1 * t2);
    }
    const double sign = (n % 2 == 0) ? 1.0 : -1.0;
    return (a.mean_factor + 2.0 * sign * a.kernel[f]) * a.amplitude * std::tanh(a.inverse_width * (static_cast<double>(n) - n0));
  };
  Eigen::VectorXd z(static_cast<Index>(fields) * sites);
  for (Index i = 0; i < sites; ++i) {
    const Index n = i - half;
    for (std::size_t f = 0; f < fields; ++f) {
      const Index at = static_cast<Index>(f) * sites + i;
      if (!a.mean_flow)
        z(at) = u(f, n);
      else if (f == 0)
        z(at) = u(0, n) - u(0, n - 1);
      else
        z(at) = u(f, n) - u(0, n);
    }
  }
  return z;
}

Eigen::VectorXd dark_seed_half_period(const DarkAnsatz& ansatz, DarkCenter center, Index sites) {
  DarkAnsatz later = ansatz;
  for (double& k : later.kernel) k = -k;
  return dark_seed(later, center, sites);
}

double dark_seed_centre(const DarkAnsatz& a, DarkCenter center, Index sites) {
  const double n0 = dark_center_n0(center);
  return a.theta != 0 ? 0.5 * static_cast<double>(sites - 1) + n0 : 0.25 * static_cast<double>(sites) + n0;
}

}  // namespace lrchain::sim::dark

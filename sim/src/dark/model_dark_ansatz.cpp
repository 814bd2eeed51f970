// Band edge and seed of a dark breather of any model file (model_dark_ansatz.hpp).
#include "lrchain/sim/dark/model_dark_ansatz.hpp"

#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "lrchain/errors.hpp"
#include "lrchain/sim/model_lattice_bloch.hpp"

namespace lrchain::sim::dark {

namespace {
// "defocusing", "focusing (omega'' h_tilde = ...)" or why there are no coefficients at theta = pi.
std::string edge_regime(const Model& model, std::size_t branch, bool& defocusing) {
  defocusing = false;
  try {
    const NlsCoefficients c = coefficients(model, branch, std::numbers::pi);
    defocusing = c.regime == Regime::defocusing;
    if (c.regime == Regime::singular) return "singular";
    return fmt::format("{} (omega'' h_tilde = {:.4g})", to_string(c.regime), c.curvature * c.h_tilde);
  } catch (const InvalidParameter&) {
    return "no real frequency";
  }
}
}  // namespace

std::size_t defocusing_edge(const Model& model, std::optional<std::size_t> branch) {
  const auto& names = model.definition().branch_names;
  std::string checked;
  for (std::size_t b = 0; b < names.size(); ++b) {
    if (branch && *branch != b) continue;
    bool defocusing = false;
    const std::string regime = edge_regime(model, b, defocusing);
    if (defocusing) return b;
    checked += fmt::format("{}{} at theta = pi: {}", checked.empty() ? "" : "; ", names[b], regime);
  }
  throw InvalidParameter("branch", fmt::format("{} has no defocusing band edge for dark breathers (edges checked: {}; "
                                               "theta = 0 edges do not fit an odd periodic ring)",
                                               model.name(), checked));
}

ModelDarkAnsatz make_model_dark_ansatz(const Model& model, const lrchain_lattice_kernels& kernels,
                                       std::size_t branch, double omega_b) {
  const NlsCoefficients c = coefficients(model, branch, std::numbers::pi);
  if (c.regime != Regime::defocusing)
    throw InvalidParameter("branch", fmt::format("the theta = pi edge of {} branch {} is not defocusing",
                                                 model.name(), model.definition().branch_names.at(branch)));
  const double detuning = 3.0 * (omega_b - c.omega);
  if (!(std::isfinite(omega_b) && omega_b > 0.0 && detuning / c.h_tilde > 0.0))
    throw InvalidParameter("omega-b", fmt::format("must lie {} the theta = pi edge omega = {:.10g} of {} branch {} "
                                                  "(the side where (omega_b - omega) h_tilde > 0, h_tilde = {:.6g})",
                                                  c.h_tilde < 0 ? "below" : "above", c.omega, model.name(),
                                                  model.definition().branch_names.at(branch), c.h_tilde));
  ModelDarkAnsatz a;
  a.branch = branch;
  a.theta = std::numbers::pi;
  a.omega_b = omega_b;
  a.omega = c.omega;
  a.curvature = c.curvature;
  a.h_tilde = c.h_tilde;
  a.mean_flow = model.definition().mean_flow;
  a.lambda = a.mean_flow ? c.lambda : 0.0;
  a.amplitude = std::sqrt(detuning / c.h_tilde);
  a.inverse_width = std::sqrt(detuning / c.curvature);
  a.mean_factor = a.mean_flow ? -c.lambda * std::sqrt(c.curvature * c.h_tilde) / std::abs(c.h_tilde) : 0.0;
  for (const auto& k : bloch_mode(model, kernels, branch, std::numbers::pi).kernel) a.kernel.push_back(k.real());
  return a;
}

// u_f[n] = (M + 2 K_f (-1)^n) A tanh(eta (n - n0)) at t = 0, in the lattice's variables.
Eigen::VectorXd model_dark_seed(const ModelDarkAnsatz& a, DarkCenter center, int sites) {
  const double n0 = dark_center_n0(center);
  const int half = (sites - 1) / 2;
  const std::size_t fields = a.kernel.size();
  auto u = [&](std::size_t f, int n) {
    const double sign = (n % 2 == 0) ? 1.0 : -1.0;
    return (a.mean_factor + 2.0 * sign * a.kernel[f]) * a.amplitude * std::tanh(a.inverse_width * (n - n0));
  };
  Eigen::VectorXd z(static_cast<Eigen::Index>(fields) * sites);
  for (int i = 0; i < sites; ++i) {
    const int n = i - half;
    for (std::size_t f = 0; f < fields; ++f) {
      const Eigen::Index at = static_cast<Eigen::Index>(f) * sites + i;
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

}  // namespace lrchain::sim::dark

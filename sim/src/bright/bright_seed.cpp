// The focusing band edge and the NLS seed of an exact bright breather (bright_seed.hpp).
#include "lrchain/sim/bright/bright_seed.hpp"

#include <cmath>
#include <functional>
#include <numbers>

#include <fmt/format.h>

#include "lrchain/errors.hpp"
#include "lrchain/sim/dark/dark_ansatz.hpp"

namespace lrchain::sim::bright {

namespace {

// Visits the band edges of `branch` (none: every branch, in the file's order), theta = pi before 0, each
// with its NLS regime and the text for messages (`visit` may add to it; it returns true to stop there);
// returns the list of the edges visited, "NAME at theta = pi: TEXT; ...".
std::string visit_band_edges(const Model& model, std::optional<Index> branch,
                             const std::function<bool(Index, double, Regime, std::string&)>& visit) {
  const auto& names = model.definition().branch_names;
  std::string checked;
  for (Index b = 0; b < Index(names.size()); ++b) {
    if (branch && *branch != b) continue;
    for (const double theta : {std::numbers::pi, 0.0}) {
      Regime regime = Regime::singular;
      std::string text = dark::band_edge_regime(model, b, theta, regime);
      const bool stop = visit(b, theta, regime, text);
      checked += fmt::format("{}{} at theta = {}: {}", checked.empty() ? "" : "; ", names[std::size_t(b)],
                             theta == 0 ? "0" : "pi", text);
      if (stop) return checked;
    }
  }
  return checked;
}

}  // namespace

FocusingEdge focusing_edge(const Model& model, std::optional<Index> branch, double omega_b) {
  std::optional<FocusingEdge> best;
  const std::string checked = visit_band_edges(model, branch, [&](Index b, double theta, Regime regime, std::string& text) {
    if (regime == Regime::focusing) {
      const NlsCoefficients c = coefficients_from_evaluators(model, b, theta);
      const bool outside = (omega_b - c.omega) * c.h_tilde > 0;
      text += fmt::format(", omega = {:.10g}, breathers {} it", c.omega, c.h_tilde > 0 ? "above" : "below");
      if (outside && (!best || std::abs(omega_b - c.omega) < std::abs(omega_b - best->nls.omega)))
        best = FocusingEdge{b, theta, c};
    }
    return false;
  });
  if (!best)
    throw InvalidParameter("omega_b", fmt::format("{} has no focusing band edge that a bright breather at omega_b = "
                                                  "{:.10g} bifurcates from (edges checked: {})",
                                                  model.name(), omega_b, checked));
  return *best;
}

FocusingEdge first_focusing_edge(const Model& model, std::optional<Index> branch) {
  std::optional<FocusingEdge> first;
  const std::string checked = visit_band_edges(model, branch, [&](Index b, double theta, Regime regime, std::string&) {
    if (regime == Regime::focusing) first = FocusingEdge{b, theta, coefficients_from_evaluators(model, b, theta)};
    return first.has_value();
  });
  if (!first)
    throw InvalidParameter("branch", fmt::format("{} has no focusing band edge for bright breathers (edges checked: {})",
                                                 model.name(), checked));
  return *first;
}

ModelBrightAnsatz bright_ansatz(const Model& model, const lrchain_lattice_kernels& kernels, const FocusingEdge& edge,
                                double omega_b, DarkCenter center) {
  return ModelBrightAnsatz(model, kernels, edge.branch, edge.theta, omega_b - edge.nls.omega, dark_center_n0(center),
                           true);
}

void check_bright_sites(Index sites) {
  if (sites < 9 || sites % 2 == 0)
    throw InvalidParameter("sites", fmt::format("must be an odd integer >= 9 (the middle site is the centre), got {}", sites));
}

// Site i is n = i - (sites - 1)/2; the ansatz's envelope is centred at its n0 (0 or 1/2).
Eigen::VectorXd bright_seed(const ModelBrightAnsatz& ansatz, bool mean_flow, Index fields, Index sites) {
  check_bright_sites(sites);
  const Index half = (sites - 1) / 2;
  auto u = [&](Index f, Index n) {
    double value = 0, rate = 0;
    ansatz.field(f, double(n), 0.0, value, rate);
    return value;
  };
  Eigen::VectorXd z(fields * sites);
  for (Index i = 0; i < sites; ++i) {
    const Index n = i - half;
    for (Index f = 0; f < fields; ++f) {
      const Index at = f * sites + i;
      if (!mean_flow) z(at) = u(f, n);
      else if (f == 0) z(at) = u(0, n) - u(0, n - 1);
      else z(at) = u(f, n) - u(0, n);
    }
  }
  return z;
}

}  // namespace lrchain::sim::bright

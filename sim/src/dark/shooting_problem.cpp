// Newton on a dark-breather shooting formulation and the shooting modes (shooting_problem.hpp).
#include "lrchain/sim/dark/shooting_problem.hpp"

#include <cmath>
#include <string>

#include <fmt/format.h>

#include "lrchain/errors.hpp"

namespace lrchain::sim::dark {

std::string_view to_string(ShootingMode m) { return m == ShootingMode::reversible ? "reversible" : "full"; }

ShootingMode parse_shooting_mode(std::string_view text) {
  if (text == "reversible") return ShootingMode::reversible;
  if (text == "full") return ShootingMode::full;
  throw InvalidParameter("mode", "must be 'reversible' (half/quarter period) or 'full', got '" +
                                     std::string(text) + "'");
}

double state_amplitude(const DarkShootingProblem& shooting, const Eigen::VectorXd& q) {
  const Eigen::VectorXd z = shooting.z_from_unknowns(q);
  return z.size() == 0 ? 0.0 : (z.array() - z.mean()).abs().maxCoeff();
}

namespace {
// Empty if Z(0) = B q is a breather; why not if its amplitude collapsed to round-off (<= 1e-8) of the
// seed's: Newton found the trivial zero of F, not a breather.
std::string trivial_state_failure(const DarkShootingProblem& shooting, const Eigen::VectorXd& q,
                                  double seed_amplitude) {
  if (state_amplitude(shooting, q) > trivial_state_ratio * seed_amplitude) return {};
  return "converged to the trivial state (no breather at this omega_b and sites); try more sites or "
         "omega_b closer to the band edge";
}
}  // namespace

NewtonResult newton_iterate(const DarkShootingProblem& shooting, Eigen::VectorXd q0, const NewtonOptions& options,
                            const NewtonLinearization& linearize, const NewtonStep& step_of) {
  NewtonResult result;
  const double seed_amplitude = state_amplitude(shooting, q0);
  result.q = std::move(q0);
  Eigen::VectorXd r;
  double first = -1;
  for (Index it = 0; it <= options.max_iterations; ++it) {
    linearize(result.q, r);
    NewtonRecord rec;
    rec.iteration = it;
    rec.residual = r.lpNorm<Eigen::Infinity>();
    if (!std::isfinite(rec.residual)) {
      result.failure = "residual is not finite";
      result.history.push_back(rec);
      if (options.progress) options.progress(rec);
      return result;
    }
    if (first < 0) first = rec.residual;
    if (rec.residual <= options.tolerance) {
      result.failure = trivial_state_failure(shooting, result.q, seed_amplitude);
      result.converged = result.failure.empty();
      result.history.push_back(rec);
      if (options.progress) options.progress(rec);
      return result;
    }
    if (it == options.max_iterations) {
      result.failure = "no convergence in " + std::to_string(options.max_iterations) + " iterations";
      result.history.push_back(rec);
      if (options.progress) options.progress(rec);
      return result;
    }
    if (rec.residual > 1e3 * std::max(first, 1e-6)) {
      result.failure = "diverging (residual grew by more than 1e3)";
      result.history.push_back(rec);
      if (options.progress) options.progress(rec);
      return result;
    }
    const Eigen::VectorXd step = step_of(result.q, r);
    rec.step = step.lpNorm<Eigen::Infinity>();
    result.history.push_back(rec);
    if (options.progress) options.progress(rec);
    result.q += step;
  }
  return result;
}

NewtonResult newton_solve(const DarkShootingProblem& shooting, Eigen::VectorXd q0, double omega_b,
                          const NewtonOptions& options) {
  Eigen::MatrixXd J;
  const Index k = shooting.unknowns();
  return newton_iterate(
      shooting, std::move(q0), options,
      [&](const Eigen::VectorXd& q, Eigen::VectorXd& r) { shooting.evaluate(q, omega_b, r, &J); },
      [&](const Eigen::VectorXd&, const Eigen::VectorXd& r) -> Eigen::VectorXd {
        return J.leftCols(k).colPivHouseholderQr().solve(-r);
      });
}

std::string newton_failure_message(const NewtonResult& result, double omega_b) {
  std::string history;
  for (const auto& record : result.history) history += fmt::format(" {:.3e}", record.residual);
  return fmt::format("Newton found no breather at omega_b = {}: {}; residual history:{}", omega_b, result.failure,
                     history);
}

}  // namespace lrchain::sim::dark

#pragma once
// What Newton and the continuation need of a dark-breather shooting formulation, and Newton itself
// (Sec. 5.3): the residual F(q, omega_b) of the unknowns q, its Jacobian from the variational
// equations, the Floquet multipliers and measures of a converged point. Implemented by DarkShooting
// (any model file, shooting.hpp) and ResonantChainShooting (the paper's chain, resonant_chain_shooting.hpp).
#include <Eigen/Dense>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "lrchain/index.hpp"

namespace lrchain::sim::dark {

enum class ShootingMode { reversible, full };
std::string_view to_string(ShootingMode m);
ShootingMode parse_shooting_mode(std::string_view text);  // InvalidParameter("mode")

struct FloquetResult;
struct DarkMeasures;

// What Newton and the continuation need of a shooting formulation: the shooting residual and its
// Jacobian, the Floquet multipliers and the measures of a converged point. ResonantChainShooting (the
// resonant chain's strain lattice, eq:Hertzd0S) and DarkShooting (any model file) provide it.
class DarkShootingProblem {
 public:
  virtual ~DarkShootingProblem() = default;
  virtual Index unknowns() const = 0;
  virtual Eigen::VectorXd z_from_unknowns(const Eigen::VectorXd& q) const = 0;
  // Residual F(q, omega_b); if jacobian != nullptr also [dF/dq | dF/domega_b] (unknowns()+1 cols).
  virtual void evaluate(const Eigen::VectorXd& q, double omega_b, Eigen::VectorXd& residual,
                        Eigen::MatrixXd* jacobian, Eigen::MatrixXd* propagator = nullptr) const = 0;
  // At a converged point: the Jacobian, and the Floquet multipliers into *floquet if not null.
  virtual void jacobian_and_floquet(const Eigen::VectorXd& q, double omega_b, Eigen::VectorXd& residual,
                                    Eigen::MatrixXd& jacobian, FloquetResult* floquet) const = 0;
  // Measures (eq:center, eq:amp, eq:l2norm, eq:relerr) of the breather Z(0) = z0.
  virtual void measure(const Eigen::VectorXd& z0, double omega_b, DarkMeasures& out) const = 0;
  // Sign changes of the one-sided contacts' overlaps over one period T_b of the orbit from Z(0) = z0
  // where the problem locates them (a model lattice with contacts); nullopt where it does not.
  virtual std::optional<Index> contact_changes_per_period(const Eigen::VectorXd&, double) const { return std::nullopt; }
  // The continuation parameter: the second argument of evaluate, measure, ... is omega_b here; a
  // problem continued in a model parameter (parameter_shooting.hpp) takes that parameter's value
  // instead, at a fixed omega_b.
  virtual std::string parameter_name() const { return "omega_b"; }
  virtual double omega_b_at(double parameter) const { return parameter; }
  // Whether the corrector may evaluate at this parameter value (omega_b > 0: T_b < 0 makes any Z(0)
  // at rest a solution; a model parameter inside its range).
  virtual bool parameter_allowed(double value) const { return value > 0.0; }
};

struct NewtonRecord {
  Index iteration = 0;
  double residual = 0;  // max-norm of F before the step
  double step = 0;      // max-norm of the Newton step taken after it (0 for the last)
};

struct NewtonOptions {
  double tolerance = 1e-11;  // converged when max|F| <= tolerance
  Index max_iterations = 20;
  std::function<void(const NewtonRecord&)> progress;  // e.g. print to stderr
};

struct NewtonResult {
  Eigen::VectorXd q;
  bool converged = false;
  std::vector<NewtonRecord> history;
  std::string failure;  // why not converged
};

// Amplitude max_i |z_i - mean(z)| of the state Z(0) = B q; zero for the trivial (uniform) state,
// which solves F = 0 at every omega_b.
double state_amplitude(const DarkShootingProblem& shooting, const Eigen::VectorXd& q);

// A zero of F whose amplitude fell to this fraction of a breather's is the trivial state.
inline constexpr double trivial_state_ratio = 1e-8;

// Newton's loop (Sec. 5.3), shared by the dense Newton and Newton-Krylov (newton_krylov.hpp):
// linearize(q, r) evaluates the residual F(q) into r (and whatever the step needs), step(q, r) returns
// the Newton step dq; the convergence test, the trivial-state check and the failures are the loop's.
using NewtonLinearization = std::function<void(const Eigen::VectorXd& q, Eigen::VectorXd& residual)>;
using NewtonStep = std::function<Eigen::VectorXd(const Eigen::VectorXd& q, const Eigen::VectorXd& residual)>;
NewtonResult newton_iterate(const DarkShootingProblem& shooting, Eigen::VectorXd q0, const NewtonOptions& options,
                            const NewtonLinearization& linearize, const NewtonStep& step);

// Newton (least squares, column-pivoting QR) on F(., omega_b) = 0 from q0 (Sec. 5.3). A zero of F
// whose amplitude max|z - mean(z)| fell below 1e-8 of the seed's is the trivial state, no breather:
// reported as not converged, failure "converged to the trivial state ...".
NewtonResult newton_solve(const DarkShootingProblem& shooting, Eigen::VectorXd q0, double omega_b,
                          const NewtonOptions& options);

// The message of a solve that did not converge: "Newton found no breather at omega_b = 1.6:
// <failure>; residual history: 3.188e+00 1.208e+00 ...".
std::string newton_failure_message(const NewtonResult& result, double omega_b);

}  // namespace lrchain::sim::dark

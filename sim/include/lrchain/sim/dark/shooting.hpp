#pragma once
// Shooting formulation of stationary dark breathers of any model file (the model's generated
// lattice kernels, model_lattice.hpp, on a periodic ring: strain form for translation-invariant
// models, displacement form for on-site models). Unknowns: all positions Z(0) (velocities 0).
// Residuals:
//  * reversible (default): Zdot(T_b/2) = 0 (time reversal makes the orbit T_b-periodic);
//  * full: Z(T_b) - Z(0) = 0, Zdot(T_b) = 0 (least squares; a check of the reversible one);
// plus, for translation-invariant models, the row C_x = (r_0(0) + r_0(T_b/2))/2 = 0 at the far site
// that fixes the conserved total strain (as the resonant chain's resonant_chain_shooting.hpp). The Jacobian comes
// from the variational equations of the generated Jacobian action, integrated on the orbit's own
// Runge-Kutta-Fehlberg 7(8) steps (the exact derivative of the discrete flow). Floquet multipliers
// from the full-period monodromy, so that the (lambda, 1/lambda) pairing is a check, not built in.
// Models with one-sided contacts (ContactBonds, contact_bonds.hpp) are integrated by ContactIntegrator:
// every contact change (an overlap s_n changing sign) is located and a step ends there, and the
// tangents are integrated on those same steps. Smooth models use Odeint's adaptive RKF78 stepping.
#include <Eigen/Dense>
#include <atomic>
#include <memory>
#include <vector>

#include "lrchain/index.hpp"
#include "lrchain/sim/dark/contact_bonds.hpp"
#include "lrchain/sim/dark/contact_integrator.hpp"
#include "lrchain/sim/dark/measures.hpp"
#include "lrchain/sim/dark/shooting_problem.hpp"
#include "lrchain/sim/model_lattice.hpp"

namespace lrchain::sim::dark {

// The periodic orbit of a model lattice and its variational equations. Not thread-safe (scratch).
class DarkOrbit {
 public:
  // Throws InvalidParameter("sites") unless sites >= 9 (check_dark_sites checks the parity).
  // `bonds`: the model's one-sided contacts in the lattice form's variables (empty: a smooth model).
  DarkOrbit(const lrchain_lattice_kernels& kernels, std::vector<double> parameters, Index sites, bool mean_flow,
                 ContactIntegrationOptions options = {}, ContactBonds bonds = {});
  ~DarkOrbit();
  DarkOrbit(const DarkOrbit&) = delete;  // its contact integrator refers to it
  DarkOrbit& operator=(const DarkOrbit&) = delete;
  Index sites() const { return sites_; }
  Index positions() const { return positions_; }  // fields x sites
  const CompiledLattice& lattice() const { return lattice_; }
  const ContactIntegrationOptions& options() const { return options_; }
  const ContactBonds& contact_bonds() const { return bonds_; }
  // Contact changes located by the integrations since the orbit was made (0 for smooth models).
  Index contact_changes() const;
  // Accepted steps of a smooth orbit are recorded (for the tangents) at most this many at a time,
  // so that memory stays bounded however many steps an integration takes.
  static constexpr std::size_t chunk_steps = 4096;
  // Step starts held for the tangent replay (bounded by chunk_steps for smooth models).
  std::size_t recorded_step_capacity() const { return times_.capacity(); }

  // Integrates [q qdot] (2 positions() entries) from t0 to t1 with error control (RKF78).
  void integrate(std::vector<double>& state, double t0, double t1) const;
  // The same, and the tangent columns phi (2 positions() rows) along: Phi(t1) Phi(t0)^-1 phi.
  void integrate(std::vector<double>& state, Eigen::MatrixXd& phi, double t0, double t1) const;
  // [qdot, qddot] of state s.
  void rhs(const double* s, double* ds) const;
  // The accepted steps of one integration, all of them (for the matrix-free products of
  // newton_krylov.hpp and krylov_floquet.hpp, which replay them once per product).
  struct RecordedSteps {
    std::vector<double> start, size;
  };
  // Integrates state from t0 to t1 with error control (as integrate) and records every accepted
  // step into `steps`; state NaN and steps empty when the orbit ran away.
  void record(std::vector<double>& state, double t0, double t1, RecordedSteps& steps) const;
  // Orbit and `columns` tangents, extended = [state | tangent 1 | ...] (each 2 positions()), advanced
  // together on the recorded steps: the derivative of the discrete flow, as integrate(state, phi, ...).
  // Allocates nothing once the stepper has seen this extended size.
  void replay(const RecordedSteps& steps, std::vector<double>& extended, Index columns) const;

 private:
  struct Steppers;
  class Contacts;  // the lattice as a ContactSystem
  CompiledLattice lattice_;
  Index sites_;
  Index positions_;
  ContactIntegrationOptions options_;
  std::unique_ptr<Steppers> steppers_;
  ContactBonds bonds_;
  std::unique_ptr<Contacts> contacts_;
  std::unique_ptr<ContactIntegrator> contact_integrator_;  // with bonds only
  struct AdaptiveRun;  // odeint's adaptive RKF78 stepping from t0 to t1, one accepted step at a time
  // Up to chunk_steps accepted steps of `run` (their starts and sizes into times_, steps_ when
  // `record`); false once the run is over: at its end time, or abandoned as running away (state NaN).
  bool smooth_chunk(AdaptiveRun& run, std::vector<double>& state, bool record) const;
  mutable OrbitRecord record_;
  mutable std::vector<double> times_, steps_, extended_, orbit_only_;  // accepted step starts and sizes
};

class DarkShooting : public DarkShootingProblem {
 public:
  DarkShooting(const lrchain_lattice_kernels& kernels, std::vector<double> parameters, Index sites, bool mean_flow,
                    ShootingMode mode, ContactIntegrationOptions options = {}, ContactBonds bonds = {});
  Index sites() const { return orbit_.sites(); }
  Index unknowns() const override { return orbit_.positions(); }
  Eigen::VectorXd z_from_unknowns(const Eigen::VectorXd& q) const override { return q; }
  ShootingMode mode() const { return mode_; }
  bool mean_flow() const { return mean_flow_; }
  const DarkOrbit& orbit() const { return orbit_; }

  void evaluate(const Eigen::VectorXd& q, double omega_b, Eigen::VectorXd& residual, Eigen::MatrixXd* jacobian,
                Eigen::MatrixXd* propagator = nullptr) const override;
  void jacobian_and_floquet(const Eigen::VectorXd& q, double omega_b, Eigen::VectorXd& residual,
                            Eigen::MatrixXd& jacobian, FloquetResult* floquet) const override;
  void measure(const Eigen::VectorXd& z0, double omega_b, DarkMeasures& out) const override;
  // Monodromy matrix Phi(T_b) of the variational equations (2 positions() square).
  Eigen::MatrixXd monodromy(const Eigen::VectorXd& z0, double omega_b) const;
  // Advances an orbit state (for measures and evolution).
  OrbitAdvance advance() const;
  // Contact changes over one period T_b of the orbit from Z(0) = z0 (nullopt for a smooth model).
  std::optional<Index> contact_changes_per_period(const Eigen::VectorXd& z0, double omega_b) const override;

 private:
  DarkOrbit orbit_;
  bool mean_flow_;
  ShootingMode mode_;
};

}  // namespace lrchain::sim::dark

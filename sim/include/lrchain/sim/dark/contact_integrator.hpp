#pragma once
// Time integration of a lattice orbit with one-sided contacts (the strain lattice of
// strain_variational.hpp, or any model lattice through ContactSystem) with Boost.Odeint's
// Runge-Kutta-Fehlberg 7(8) error stepper, error control on the orbit, and steps that end exactly
// at contact changes (x_n(t) = delta0 for the strain lattice), where a force such as the
// (delta0 - x)_+^(3/2) of eq:Vr is not smooth.
//
// Why not odeint's integrate_adaptive: a step that straddles or merely touches a contact change
// sees a |t - t*|^(3/2) singularity; the embedded error estimate misjudges it and E_b(T_b) stalls
// near 1e-9. Here every contact change is located (cubic Hermite in x, xdot + Boost.Math TOMS 748),
// the step is cut there, and steps next to a contact change are graded geometrically down to
// `contact_step`. The Runge-Kutta stages are Odeint's.
//
// Optionally records, for every accepted step, (t, dt) and V''(x) at each of the 13 stages (the
// strain lattice; a ContactSystem records what its stiffness_count() says, possibly nothing), so
// that the variational equations can be integrated afterwards with exactly the same steps
// (tangent_propagation.hpp): the Jacobian is then the exact derivative of the discrete flow.
#include <atomic>
#include <cstddef>
#include <memory>
#include <vector>

#include "lrchain/index.hpp"
#include "lrchain/sim/dark/strain_variational.hpp"

namespace lrchain::sim::dark {

struct ContactIntegrationOptions {
  double rel_tol = 1e-13;      // relative error per step on the orbit components
  double abs_tol = 1e-14;      // absolute error per step on the orbit components
  double max_step = 0.25;      // upper bound on a step (time units of Sec. 2)
  double initial_step = 0.02;
  double min_step = 1e-13;     // below this the integration throws std::runtime_error
  // More accepted steps than 1000 + this times the interval abandon the orbit as running away (a
  // guess far outside the force's range oscillates ever faster): smooth model orbits (DarkOrbit)
  // become NaN, the contact integrator throws NumericalFailure (its OrbitRecord stays bounded).
  double max_steps_per_time = 1e5;
  double contact_step = 1e-4;  // step next to a contact change (steps grade geometrically from it)
  double grading = 3.0;        // growth factor of steps away from a contact change
  double group_window = 1e-7;  // contact changes closer than this are crossed in one step
  bool locate_contacts = true; // false: plain adaptive stepping across kinks (for comparison)
  // Set (SIGINT from Python): integrate() and propagate_tangents() throw Interrupted at their next step.
  const std::atomic<bool>* stop = nullptr;
};

struct ContactIntegrationStats {
  Index steps = 0;          // accepted steps
  Index rejected = 0;       // trial steps rejected (error test or a contact change inside)
  Index contact_cuts = 0;   // steps ended at a contact change (a group of them)
  Index contact_changes = 0;  // sign changes of contact functions over accepted steps
};

// A first-order system whose right-hand side is smooth except where one of its contact functions
// changes sign (a one-sided contact opening or closing).
class ContactSystem {
 public:
  virtual ~ContactSystem() = default;
  virtual Index dimension() const = 0;
  // Entries written per stage into `stiffness` by rhs() (0: nothing recorded).
  virtual Index stiffness_count() const = 0;
  // ds = d/dt s; if stiffness != nullptr it receives stiffness_count() values.
  virtual void rhs(const double* s, double* ds, double* stiffness) const = 0;
  virtual Index contact_count() const = 0;
  // The contact functions at s and their time derivatives along the flow (linear in the positions,
  // so the rates follow from the velocities).
  virtual void contacts(const double* s, double* value, double* rate) const = 0;
};

// Accepted steps of one integration and the stage stiffnesses V''(x) (13 stages x N per step).
struct OrbitRecord {
  static constexpr Index stages = 13;  // Runge-Kutta-Fehlberg 7(8)
  Index sites = 0;
  std::vector<double> t, dt;
  std::vector<double> stiffness;  // [step][stage][site]
  Index steps() const { return static_cast<Index>(dt.size()); }
  const double* stage(Index step, Index stage) const { return stiffness.data() + (step * stages + stage) * sites; }
  void clear() { t.clear(); dt.clear(); stiffness.clear(); }
};

class ContactIntegrator {
 public:
  ContactIntegrator(const StrainLatticeOrbit& orbit, ContactIntegrationOptions options = {});
  // Any ContactSystem, kept by reference: it must outlive the integrator.
  ContactIntegrator(const ContactSystem& system, ContactIntegrationOptions options = {});
  ~ContactIntegrator();
  ContactIntegrator(const ContactIntegrator&) = delete;
  ContactIntegrator& operator=(const ContactIntegrator&) = delete;
  // Integrates the orbit state [x y xdot ydot] from t0 to t1 in place; appends to *record if given.
  void integrate(std::vector<double>& state, double t0, double t1, OrbitRecord* record = nullptr);
  const ContactIntegrationStats& stats() const { return stats_; }

 private:
  double error_norm(const std::vector<double>& in, const std::vector<double>& out) const;
  // Earliest contact change in (0, h] (end of its group), or h if none.
  double first_contact(double h) const;
  void trial(const std::vector<double>& in, double t, double h);
  // Smallest time until some x_n reaches delta0 by linear extrapolation from the end state.
  double time_to_contact() const;

  struct Stepper;  // Odeint RKF78 stepper (stage storage sized for this orbit)
  std::unique_ptr<Stepper> stepper_;
  std::unique_ptr<ContactSystem> owned_;  // the strain lattice's adapter
  const ContactSystem& system_;
  ContactIntegrationOptions options_;
  ContactIntegrationStats stats_;
  double h_;
  std::vector<double> out_, err_, trial_stiffness_;
  // Contact functions and rates at the start (in) and end (out) of the trial step.
  std::vector<double> contact_in_, rate_in_, contact_out_, rate_out_;
  Index calls_ = 0;
  double last_t_ = -1e300, cap_ = 0, target_ = -1, contact_step_ = 0;
  bool recording_ = false;
};

}  // namespace lrchain::sim::dark

#include "lrchain/sim/dark/contact_integrator.hpp"

#include <algorithm>
#include <boost/math/tools/roots.hpp>
#include <fmt/format.h>
#include <boost/numeric/odeint/stepper/runge_kutta_fehlberg78.hpp>
#include <cmath>
#include <csignal>
#include <limits>
#include <stdexcept>
#include <string>

#include "lrchain/errors.hpp"

namespace lrchain::sim::dark {

namespace {
using State = std::vector<double>;
using Rkf78 = boost::numeric::odeint::runge_kutta_fehlberg78<State>;

// Cubic Hermite interpolant on [0, h] from values x0, x1 and slopes v0, v1, at s in [0, 1].
inline double hermite(double x0, double v0, double x1, double v1, double h, double s) {
  const double s2 = s * s, s3 = s2 * s;
  return (2 * s3 - 3 * s2 + 1) * x0 + (s3 - 2 * s2 + s) * h * v0 + (-2 * s3 + 3 * s2) * x1 +
         (s3 - s2) * h * v1;
}
}  // namespace

struct ContactIntegrator::Stepper {
  Rkf78 rk;
};

namespace {
// The strain lattice as a ContactSystem: contact functions x_n - delta0 (eq:Vr), stiffness V''(x_n).
class StrainContactSystem final : public ContactSystem {
 public:
  explicit StrainContactSystem(const StrainLatticeOrbit& orbit) : orbit_(orbit) {}
  Index dimension() const override { return orbit_.orbit_size(); }
  Index stiffness_count() const override { return orbit_.sites(); }
  void rhs(const double* s, double* ds, double* stiffness) const override { orbit_.rhs(s, ds, stiffness); }
  Index contact_count() const override { return orbit_.sites(); }
  void contacts(const double* s, double* value, double* rate) const override {
    const Index N = orbit_.sites();
    const double d0 = orbit_.params().delta0;
    for (Index n = 0; n < N; ++n) {
      value[n] = s[n] - d0;
      rate[n] = s[2 * N + n];
    }
  }

 private:
  const StrainLatticeOrbit& orbit_;
};
}  // namespace

ContactIntegrator::~ContactIntegrator() = default;

ContactIntegrator::ContactIntegrator(const StrainLatticeOrbit& orbit, ContactIntegrationOptions options)
    : stepper_(std::make_unique<Stepper>()), owned_(std::make_unique<StrainContactSystem>(orbit)),
      system_(*owned_), options_(options), h_(options.initial_step) {
  trial_stiffness_.resize(static_cast<std::size_t>(OrbitRecord::stages * system_.stiffness_count()));
}

ContactIntegrator::ContactIntegrator(const ContactSystem& system, ContactIntegrationOptions options)
    : stepper_(std::make_unique<Stepper>()), system_(system), options_(options), h_(options.initial_step) {
  trial_stiffness_.resize(static_cast<std::size_t>(OrbitRecord::stages * system_.stiffness_count()));
}

double ContactIntegrator::error_norm(const State& in, const State& out) const {
  double e = 0.0;
  for (std::size_t i = 0; i < in.size(); ++i) {
    const double scale =
        options_.abs_tol + options_.rel_tol * std::max(std::abs(in[i]), std::abs(out[i]));
    e = std::max(e, std::abs(err_[i]) / scale);
  }
  return e;
}

double ContactIntegrator::first_contact(double h) const {
  const Index N = system_.contact_count();
  const double ignore = 1e-11;  // a crossing at the very start: we are sitting on that kink
  // First time in (0, h] where the cubic Hermite interpolant of contact function n changes sign,
  // or -1. The cubic is split at its interior extrema so that a grazing contact (x_n crosses
  // delta0 and comes back within one step, equal signs at both ends) is found too.
  auto crossing = [&](std::size_t n) -> double {
    const double x0 = contact_in_[n], x1 = contact_out_[n];
    const double v0 = rate_in_[n], v1 = rate_out_[n];
    auto f = [&](double s) { return hermite(x0, v0, x1, v1, h, s); };
    auto changes = [](double a, double b) { return (a < 0.0 && b >= 0.0) || (a > 0.0 && b <= 0.0); };
    // Breakpoints: 0, the roots of p'(s) = A s^2 + B s + C in (0, 1) in increasing order, 1.
    double knots[4] = {0.0, 1.0, 1.0, 1.0};
    int count = 1;
    const bool same_side = !changes(x0, x1);
    if (same_side) {
      // Only an interior extremum on the far side of delta0 can hide a contact change: the
      // velocity must point towards delta0 at the start or away from it at the end.
      const double A = 6 * x0 + 3 * h * v0 - 6 * x1 + 3 * h * v1;
      const double B = -6 * x0 - 4 * h * v0 + 6 * x1 - 2 * h * v1;
      const double C = h * v0;
      double r[2];
      int nr = 0;
      if (std::abs(A) < 1e-300) {
        if (B != 0.0) r[nr++] = -C / B;
      } else {
        const double disc = B * B - 4 * A * C;
        if (disc >= 0.0) {
          const double q = -0.5 * (B + std::copysign(std::sqrt(disc), B));
          r[nr++] = q / A;
          if (q != 0.0) r[nr++] = C / q;
        }
      }
      if (nr == 2 && r[0] > r[1]) std::swap(r[0], r[1]);
      for (int i = 0; i < nr; ++i)
        if (r[i] > 0.0 && r[i] < 1.0) knots[count++] = r[i];
      if (count == 1) return -1.0;
    }
    knots[count] = 1.0;
    double a = 0.0, fa = x0;
    for (int i = 1; i <= count; ++i) {
      const double b = knots[i], fb = i == count ? x1 : f(b);
      if (changes(fa, fb)) {
        boost::uintmax_t it = 60;
        const auto root = boost::math::tools::toms748_solve(
            f, a, b, fa, fb, boost::math::tools::eps_tolerance<double>(45), it);
        return 0.5 * (root.first + root.second) * h;
      }
      a = b;
      fa = fb;
    }
    return -1.0;
  };
  double first = std::numeric_limits<double>::infinity();
  for (std::size_t n = 0; n < std::size_t(N); ++n) {
    const double tc = crossing(n);
    if (tc > ignore && tc < first) first = tc;
  }
  if (!std::isfinite(first)) return h;
  double last = first;
  for (std::size_t n = 0; n < std::size_t(N); ++n) {
    const double tc = crossing(n);
    if (tc > first && tc <= first + options_.group_window) last = std::max(last, tc);
  }
  const double cut = last + 1e-14;  // land just past the group: next step starts beyond the kink
  return cut < h ? cut : h;
}

double ContactIntegrator::time_to_contact() const {
  const std::size_t N = std::size_t(system_.contact_count());
  double tau = std::numeric_limits<double>::infinity();
  for (std::size_t n = 0; n < N; ++n) {
    const double gap = -contact_out_[n], v = rate_out_[n];
    if (gap * v > 0.0) tau = std::min(tau, gap / v);  // moving towards the contact change
  }
  return tau;
}

void ContactIntegrator::trial(const State& in, double t, double h) {
  const std::size_t N = static_cast<std::size_t>(system_.stiffness_count());
  calls_ = 0;
  auto sys = [this, N](const State& s, State& ds, double) {
    double* g = recording_ && N > 0
                    ? trial_stiffness_.data() + static_cast<std::size_t>(std::min(calls_, OrbitRecord::stages - 1)) * N
                    : nullptr;
    ++calls_;
    system_.rhs(s.data(), ds.data(), g);
  };
  stepper_->rk.do_step(sys, in, t, out_, h, err_);
  if (calls_ != OrbitRecord::stages)
    throw std::logic_error("contact integrator: unexpected number of Runge-Kutta stages");
}

void ContactIntegrator::integrate(State& state, double t0, double t1, OrbitRecord* record) {
  if (!(t1 > t0)) return;
  recording_ = record != nullptr;
  if (record) record->sites = system_.stiffness_count();
  out_.resize(state.size());
  err_.resize(state.size());
  const std::size_t contacts = static_cast<std::size_t>(system_.contact_count());
  contact_in_.resize(contacts);
  rate_in_.resize(contacts);
  contact_out_.resize(contacts);
  rate_out_.resize(contacts);
  if (options_.locate_contacts && contacts > 0) system_.contacts(state.data(), contact_in_.data(), rate_in_.data());
  double t = t0;
  // The step size, the grading cap after a contact change and a located contact change ahead
  // (absolute time) are carried over when this call continues the previous one; a call from
  // another time starts afresh, so its steps do not depend on what the integrator did before.
  const bool continued = t0 == last_t_;
  double h = std::min(continued ? h_ : options_.initial_step, options_.max_step);
  double cap = continued ? cap_ : options_.max_step;
  double target = continued ? target_ : -1.0;
  double contact_step = continued ? contact_step_ : options_.contact_step;
  const double step_cap = 1000.0 + options_.max_steps_per_time * (t1 - t0);
  double accepted = 0;
  while (t < t1) {
    if (options_.stop && options_.stop->load(std::memory_order_relaxed)) throw Interrupted(SIGINT, "interrupted by SIGINT");
    const double remaining = t1 - t;
    double step = std::min(h, cap);
    bool landing = false;
    if (options_.locate_contacts && target > t) {
      // Remaining distances to the contact change shrink geometrically down to contact_step.
      const double r = target - t;
      const double cs = contact_step;
      if (r <= 1.5 * cs && r <= remaining) {
        step = r;
        landing = true;
      } else if (r <= 1.5 * cs) {  // the call ends first: stay graded towards the contact change
        step = r - r / options_.grading;
      } else {
        step = r - std::max({r - step, r / options_.grading, cs});
      }
    }
    // Never step past the end of this call (a contact change beyond t1 stays the target).
    const bool at_end = step >= remaining;
    if (at_end) step = remaining;
    trial(state, t, step);
    const double e = error_norm(state, out_);
    if (e > 1.0) {
      ++stats_.rejected;
      h = step * std::max(0.2, 0.9 * std::pow(e, -1.0 / 8.0));
      if (h < options_.min_step)
        throw NumericalFailure("dark-breather integration: step size below " +
                                 std::to_string(options_.min_step) + " at t = " + std::to_string(t));
      continue;
    }
    if (options_.locate_contacts && contacts > 0) {
      system_.contacts(out_.data(), contact_out_.data(), rate_out_.data());
      // Landing steps end just past the located group; an earlier contact change of another
      // site (or a grazing one) inside them is approached in turn.
      const double cut = first_contact(step);
      const double slack = landing ? options_.group_window : 0.0;
      if (cut < step - slack) {  // a contact change inside: approach it with graded steps
        ++stats_.rejected;
        target = t + cut;
        continue;
      }
      // A long step that ends just before a contact change is as inaccurate as one across it
      // (the |t - t*|^(3/2) singularity lies within its radius of convergence, and the embedded
      // error estimate does not see it): unless it is no longer than a landing step
      // (1.5 contact_step), its end must stay step / (2 (grading - 1)) away from the next contact
      // change (linear extrapolation of x_n; graded steps keep twice that).
      if (step > 1.5 * contact_step) {
        const double tau = time_to_contact();
        const double estimate = t + step + tau;
        if (tau < 0.5 * step / (options_.grading - 1.0) && (!(target > t) || estimate < target)) {
          ++stats_.rejected;
          target = estimate;
          continue;
        }
      }
    }
    const double next = step * std::min(4.0, 0.9 * std::pow(std::max(e, 1e-12), -1.0 / 8.0));
    if (++accepted > step_cap)
      throw NumericalFailure(fmt::format("dark-breather integration: more than {:.0f} steps over t = {:.6g} .. {:.6g} "
                                         "(the orbit oscillates ever faster: a guess far outside the force's range)",
                                         step_cap, t0, t1));
    state.swap(out_);
    ++stats_.steps;
    if (options_.locate_contacts && contacts > 0) {
      for (std::size_t n = 0; n < contacts; ++n) {
        const double a = contact_in_[n], b = contact_out_[n];
        if ((a < 0.0 && b >= 0.0) || (a > 0.0 && b <= 0.0)) ++stats_.contact_changes;
      }
      contact_in_.swap(contact_out_);
      rate_in_.swap(rate_out_);
    }
    if (record) {
      record->t.push_back(t);
      record->dt.push_back(step);
      record->stiffness.insert(record->stiffness.end(), trial_stiffness_.begin(),
                               trial_stiffness_.end());
    }
    t = at_end ? t1 : t + step;
    if (landing) {
      ++stats_.contact_cuts;
      target = -1.0;
      cap = contact_step;
      contact_step = options_.contact_step;
    } else {
      cap = std::min(options_.max_step, cap * options_.grading);
    }
    // The controller's step changes only when it was the limiting factor.
    if (step >= h * (1.0 - 1e-12)) h = std::min(next, options_.max_step);
  }
  h_ = h;
  cap_ = cap;
  target_ = target;
  contact_step_ = contact_step;
  last_t_ = t1;
  recording_ = false;
}

}  // namespace lrchain::sim::dark

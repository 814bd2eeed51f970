#include "lrchain/sim/dark/continuation.hpp"

#include <cmath>
#include <fmt/format.h>

#include "lrchain/errors.hpp"

namespace lrchain::sim::dark {

std::string_view to_string(BranchStop stop) {
  switch (stop) {
    case BranchStop::points: return "points";
    case BranchStop::window: return "window";
    case BranchStop::trivial_state: return "trivial_state";
    case BranchStop::step_too_small: return "step_too_small";
    case BranchStop::interrupted: return "interrupted";
  }
  return "points";
}

namespace {
// The arclength's inner product: w a_q . b_q + a_omega b_omega (omega_b last); w = 1: the plain one.
struct ArclengthMetric {
  double w = 1;
  Eigen::VectorXd weighted(const Eigen::VectorXd& a) const {  // W a
    if (w == 1) return a;
    Eigen::VectorXd out = w * a;
    out(a.size() - 1) = a(a.size() - 1);
    return out;
  }
  double dot(const Eigen::VectorXd& a, const Eigen::VectorXd& b) const { return w == 1 ? a.dot(b) : weighted(a).dot(b); }
  double norm(const Eigen::VectorXd& a) const { return w == 1 ? a.norm() : std::sqrt(dot(a, a)); }
};

// Unit tangent of {F(u) = 0} at u: [J; (W t_prev)^T] t = [0; 1] in least squares, oriented along t_prev.
Eigen::VectorXd tangent(const Eigen::MatrixXd& J, const Eigen::VectorXd& t_prev, const ArclengthMetric& metric) {
  Eigen::MatrixXd A(J.rows() + 1, J.cols());
  A.topRows(J.rows()) = J;
  A.row(J.rows()) = metric.weighted(t_prev).transpose();
  Eigen::VectorXd b = Eigen::VectorXd::Zero(A.rows());
  b(J.rows()) = 1.0;
  Eigen::VectorXd t = A.colPivHouseholderQr().solve(b);
  if (metric.w == 1) t.normalize();
  else t /= metric.norm(t);
  if (metric.dot(t, t_prev) < 0) t = -t;
  return t;
}

// The fold between points a and b, ds apart in arclength, where d omega_b/ds changes sign.
FoldPoint locate_fold(const BranchPoint& a, const BranchPoint& b, double ds, Index after) {
  FoldPoint fold;
  fold.after = after;
  const double f = a.tangent_omega / (a.tangent_omega - b.tangent_omega);  // d omega/ds = 0, linearly
  fold.fraction = f;
  // Cubic Hermite interpolant of omega_b(s) on [0, ds] at s = f ds.
  const double h00 = (1 + 2 * f) * (1 - f) * (1 - f), h10 = f * (1 - f) * (1 - f), h01 = f * f * (3 - 2 * f),
               h11 = f * f * (f - 1);
  fold.omega_b = h00 * a.parameter + h10 * ds * a.tangent_omega + h01 * b.parameter + h11 * ds * b.tangent_omega;
  fold.norm_squared = (1 - f) * a.measures.norm_squared + f * b.measures.norm_squared;
  return fold;
}
}  // namespace

BranchResult continue_branch(const DarkShootingProblem& shooting, const Eigen::VectorXd& q0, double omega0,
                             const ContinuationOptions& o,
                             const std::function<void(const BranchPoint&)>& on_point) {
  const Eigen::Index k = shooting.unknowns();
  BranchResult out;
  out.state_weight = o.state_weight;
  Eigen::VectorXd u(k + 1);
  u.head(k) = q0;
  u(k) = omega0;
  Eigen::VectorXd t_prev = Eigen::VectorXd::Zero(k + 1);
  t_prev(k) = o.direction < 0 ? -1.0 : 1.0;
  Eigen::VectorXd r;
  Eigen::MatrixXd J;
  double ds = o.ds;
  Index iterations = 0;
  ArclengthMetric metric{o.state_weight == 0 ? 1.0 / double(k) : o.state_weight};
  double last_step = 0;  // arclength from the previous point to the one being accepted

  // Accepts the converged point u: Jacobian (and Floquet propagator), measures, tangent.
  auto accept = [&](double residual) {
    BranchPoint pt;
    pt.parameter = u(k);
    pt.omega_b = shooting.omega_b_at(u(k));
    pt.z0 = shooting.z_from_unknowns(u.head(k));
    shooting.jacobian_and_floquet(u.head(k), u(k), r, J, o.floquet ? &pt.floquet : nullptr);
    shooting.measure(pt.z0, u(k), pt.measures);
    pt.contact_changes_per_period = shooting.contact_changes_per_period(pt.z0, u(k));
    pt.iterations = iterations;
    pt.residual = residual;
    if (out.points.empty() && o.state_weight == 0) {  // w |dq/domega_b|^2 = 1 along the first tangent
      const Eigen::VectorXd first = tangent(J, t_prev, metric);
      const double slope = first.head(k).squaredNorm() / (first(k) * first(k));
      if (std::isfinite(slope) && slope > 0) metric.w = std::min(metric.w, 1.0 / slope);
      out.state_weight = metric.w;
    }
    const Eigen::VectorXd t = tangent(J, t_prev, metric);
    pt.tangent_omega = t(k);
    if (!out.points.empty() && (t(k) > 0) != (out.points.back().tangent_omega > 0)) {
      out.turning_points.push_back(pt.parameter);
      out.folds.push_back(locate_fold(out.points.back(), pt, last_step, Index(out.points.size()) - 1));
    }
    t_prev = t;
    out.points.push_back(std::move(pt));
    if (on_point) on_point(out.points.back());
  };

  shooting.evaluate(u.head(k), u(k), r, nullptr);
  accept(r.lpNorm<Eigen::Infinity>());
  const double first_amplitude = state_amplitude(shooting, q0);

  // A signal ends the branch between points, between corrector iterations, or inside an integration
  // (Interrupted, when the shooting's integration options carry the stop flag): the points so far stay.
  auto interrupted = [&](double omega_b) {
    out.interrupted = true;
    out.stop = BranchStop::interrupted;
    out.stop_reason = fmt::format("interrupted after {} points at {} = {:.6f}", out.points.size(),
                                  shooting.parameter_name(), omega_b);
    return out;
  };
  auto stopped = [&] { return o.stop && o.stop->load(std::memory_order_relaxed); };
  // The solution at parameter = bound from the state interpolated between u_prev and u (Newton at
  // fixed parameter), accepted as the last point; false if Newton does not converge there.
  auto land = [&](const Eigen::VectorXd& u_prev, double bound) {
    const double f = (bound - u_prev(k)) / (u(k) - u_prev(k));
    const Eigen::VectorXd q = u_prev.head(k) + f * (u.head(k) - u_prev.head(k));
    NewtonOptions newton;
    newton.tolerance = o.tolerance;
    const NewtonResult solved = newton_solve(shooting, q, bound, newton);
    if (!solved.converged) return false;
    u.head(k) = solved.q;
    u(k) = bound;
    last_step = metric.norm(u - u_prev);
    shooting.evaluate(u.head(k), u(k), r, nullptr);
    accept(r.lpNorm<Eigen::Infinity>());
    return true;
  };
  while (Index(out.points.size()) < o.max_points) try {
    if (stopped()) return interrupted(u(k));
    const Eigen::VectorXd u_prev = u;
    const Eigen::VectorXd t = t_prev;
    // Chord corrector with the Jacobian of the last point, refreshed when it stalls.
    Eigen::MatrixXd A(J.rows() + 1, k + 1);
    A.topRows(J.rows()) = J;
    A.row(J.rows()) = metric.weighted(t).transpose();
    auto qr = A.colPivHouseholderQr();
    bool converged = false;
    double res = INFINITY, last = INFINITY;
    u = u_prev + ds * t;
    const Eigen::VectorXd u_pred = u;
    iterations = 0;
    // A predictor beyond the end of the range: the last point is solved at the end itself.
    if (o.land_on_bounds && (u(k) < o.omega_min || u(k) > o.omega_max)) {
      const double bound = u(k) < o.omega_min ? o.omega_min : o.omega_max;
      if (land(u_prev, bound)) {
        out.stop = BranchStop::window;
        out.stop_reason = fmt::format("reached {} = {:g}, the end of the range", shooting.parameter_name(), bound);
        return out;
      }
      u = u_prev;
      shooting.evaluate(u.head(k), u(k), r, &J);
      ds *= 0.5;
      if (ds < o.ds_min) {
        out.stop = BranchStop::step_too_small;
        out.stop_reason = fmt::format("arclength step below {:g} at {} = {:.6f} (Newton did not converge at {} = {:g})",
                                      o.ds_min, shooting.parameter_name(), u(k), shooting.parameter_name(), bound);
        return out;
      }
      continue;
    }
    for (Index it = 0; it < o.max_corrector; ++it) {
      if (stopped()) return interrupted(u_prev(k));
      shooting.evaluate(u.head(k), u(k), r, nullptr);
      res = r.lpNorm<Eigen::Infinity>();
      iterations = it;
      if (!std::isfinite(res)) break;
      if (res <= o.tolerance) {
        converged = true;
        break;
      }
      if (res > o.chord_contraction * last) {  // chord stalls: fresh Jacobian at the current point
        if (res > 10 * last) break;
        shooting.evaluate(u.head(k), u(k), r, &J);
        A.topRows(J.rows()) = J;
        qr = A.colPivHouseholderQr();
      }
      last = res;
      Eigen::VectorXd rhs(r.size() + 1);
      rhs.head(r.size()) = r;
      rhs(r.size()) = metric.dot(t, u - u_pred);
      u -= qr.solve(rhs);
      // A corrector that moves farther than the step itself (or to omega_b <= 0, where T_b < 0 makes
      // any Z(0) at rest a solution) has jumped off the branch: a smaller step instead.
      if (!shooting.parameter_allowed(u(k)) || metric.norm(u - u_pred) > ds) break;
    }
    if (!converged) {
      u = u_prev;
      // Restore the Jacobian of the last accepted point for the next chord attempt.
      shooting.evaluate(u.head(k), u(k), r, &J);
      ds *= 0.5;
      if (ds < o.ds_min) {
        out.stop = BranchStop::step_too_small;
        out.stop_reason = fmt::format("arclength step below {:g} at {} = {:.6f} (corrector did not "
                                      "converge, last residual {:.3g})", o.ds_min, shooting.parameter_name(), u(k), res);
        return out;
      }
      continue;
    }
    // The uniform state solves F = 0 at every omega_b: a corrector that lands on it has left the
    // breather branch, and its points are not breathers.
    if (state_amplitude(shooting, u.head(k)) <= trivial_state_ratio * first_amplitude) {
      out.stop = BranchStop::trivial_state;
      out.stop_reason = fmt::format("the branch reached the trivial (uniform) state at omega_b = {:.6f}: the "
                                    "breather's amplitude vanished", u(k));
      return out;
    }
    if (u(k) < o.omega_min || u(k) > o.omega_max) {
      out.stop = BranchStop::window;
      const double bound = u(k) < o.omega_min ? o.omega_min : o.omega_max;
      if (o.land_on_bounds && land(u_prev, bound)) {
        out.stop_reason = fmt::format("reached {} = {:g}, the end of the range", shooting.parameter_name(), bound);
        return out;
      }
      out.stop_reason = fmt::format("{} = {:.6f} left [{:g}, {:g}]", shooting.parameter_name(), u(k), o.omega_min,
                                    o.omega_max);
      return out;
    }
    last_step = metric.norm(u - u_prev);
    accept(res);
    if (iterations <= o.easy_corrector) ds = std::min(ds * 1.5, o.ds_max);
    if (iterations >= o.hard_corrector) ds *= 0.7;
  } catch (const Interrupted&) {
    return interrupted(out.points.empty() ? omega0 : out.points.back().parameter);
  }
  out.stop_reason = fmt::format("reached {} points", o.max_points);
  return out;
}

}  // namespace lrchain::sim::dark

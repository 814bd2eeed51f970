// lrchain.dark: exact stationary dark breathers (Sec. 5.3-5.4): shooting Newton from the eq:xy_app
// seed, pseudo-arclength continuation in omega_b, Floquet multipliers, direct evolution; the sim
// library's dark/ functions, run without the GIL, results as numpy arrays.
#include <algorithm>
#include <complex>
#include <fmt/format.h>
#include <numbers>
#include <pybind11/complex.h>
#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "dark_arrays.hpp"
#include "interrupt_guard.hpp"
#include "lrchain/ansatz/dark_breather.hpp"
#include "lrchain/config/option_caps.hpp"
#include "lrchain/errors.hpp"
#include "lrchain/sim/dark/continuation.hpp"
#include "lrchain/sim/dark/evolution.hpp"
#include "lrchain/sim/resource_estimate.hpp"

namespace py = pybind11;

namespace lrchain::python {

namespace {
using namespace lrchain::sim::dark;

// What every dark job starts from: the family, the ansatz at the band edge and Newton's solution.
struct DarkJob {
  Params params;
  double omega_b = 0;
  Branch edge = Branch::optical;
  DarkCenter center = DarkCenter::bond;
  Index sites = 101;
  ShootingMode mode = ShootingMode::reversible;
  double tolerance = 1e-11;
  Index max_iterations = 20;
};

DarkJob make_job(const Params& p, double omega_b, const std::string& edge, const std::string& center, Index sites,
                 const std::string& mode, double tolerance, Index max_iterations) {
  validate(p);
  DarkJob j{p, omega_b, parse_branch(edge), parse_dark_center(center), sites, parse_shooting_mode(mode),
            tolerance, max_iterations};
  make_dark_breather_ansatz(p, j.edge, omega_b);  // checks omega_b against the edge
  config::checked_option(double(sites), config::dark_sites, "sites");
  if (sites < 9 || sites % 2 == 0)
    throw InvalidParameter("sites", "must be an odd integer >= 9 (a staggered dark breather fits periodic "
                                    "ends only on an odd number of sites)");
  if (!(tolerance > 0 && tolerance < 1)) throw InvalidParameter("tolerance", "must be in (0, 1)");
  if (max_iterations < 1) throw InvalidParameter("max_iterations", "must be an integer >= 1");
  return j;
}

// Refuses a job whose Newton/Floquet matrices, recorded orbit and snapshots exceed the available
// memory (as the CLI does), naming what to change.
void check_job_memory(const DarkJob& j, bool floquet, double periods) {
  const double period = 2 * std::numbers::pi / j.omega_b;
  const double shooting_time = j.mode == ShootingMode::full || floquet
                                   ? period : (j.center == DarkCenter::site ? period / 2 : period / 4);
  const sim::ResourceEstimate e = sim::estimate_dark_breather(j.sites, floquet, shooting_time, periods);
  if (e.dominant == "period") sim::check_memory(e, 0, "omega_b", "raise omega_b (a shorter period T_b)");
  else if (e.dominant == "periods") sim::check_memory(e, 0, "t_end", "lower t_end");
  else sim::check_memory(e, 0, "sites", "lower sites");
}

struct Solved {
  DarkShooting shooting;
  DarkBreatherAnsatz ansatz;
  NewtonResult newton;
  Eigen::VectorXd seed;
};

// Newton from the eq:xy_app seed (called without the GIL); stops with Interrupted on SIGINT, also
// inside an integration (the shooting's integration options carry the stop flag, and so do the
// Floquet and evolution runs that reuse them).
Solved solve(const DarkJob& j, const std::atomic<bool>* stop) {
  const DarkBreatherAnsatz ansatz = make_dark_breather_ansatz(j.params, j.edge, j.omega_b);
  ContactIntegrationOptions integration;
  integration.stop = stop;
  DarkShooting shooting(j.params, j.sites, j.center, j.mode, integration);
  const Eigen::VectorXd seed = dark_seed(ansatz, j.center, j.sites);
  NewtonOptions o;
  o.tolerance = j.tolerance;
  o.max_iterations = j.max_iterations;
  o.progress = [stop](const NewtonRecord&) {
    if (stop->load(std::memory_order_relaxed)) throw Interrupted(SIGINT, "interrupted by SIGINT");
  };
  NewtonResult res = newton_solve(shooting, shooting.unknowns_from_z(seed), j.omega_b, o);
  return {std::move(shooting), ansatz, std::move(res), seed};
}

// Throws NumericalFailure with the residual history if Newton did not converge.
void require_converged(const DarkJob& j, const NewtonResult& r) {
  if (r.converged) return;
  throw NumericalFailure(sim::dark::newton_failure_message(r, j.omega_b));
}

// The solution as a dict: profile x_n(0), y_n(0), the seed, Newton's history, the measures (Sec. 5.3).
py::dict solution_dict(const DarkJob& j, const Solved& s, const DarkMeasures& m) {
  const Eigen::VectorXd z0 = s.shooting.z_from_unknowns(s.newton.q);
  const Index N = j.sites;
  py::array_t<double> n(N);
  for (Index i = 0; i < N; ++i) n.mutable_at(i) = i - (N - 1) / 2;
  py::dict d;
  d["n"] = n;
  d["x"] = Eigen::VectorXd(z0.head(N));
  d["y"] = Eigen::VectorXd(z0.tail(N));
  d["x_seed"] = Eigen::VectorXd(s.seed.head(N));
  d["y_seed"] = Eigen::VectorXd(s.seed.tail(N));
  d["newton_residuals"] = residuals(s.newton);
  d["omega_edge"] = s.ansatz.omega;
  d["measures"] = measures(m);
  return d;
}

py::dict solve_job(const Params& p, double omega_b, const std::string& edge, const std::string& center, Index sites,
                   const std::string& mode, double tolerance, Index max_iterations, bool floquet, bool full_monodromy) {
  const DarkJob j = make_job(p, omega_b, edge, center, sites, mode, tolerance, max_iterations);
  check_job_memory(j, floquet, 0);
  InterruptGuard guard;
  auto [s, m, f] = guard.run([&] {
    Solved s = solve(j, guard.flag());
    require_converged(j, s.newton);
    const Eigen::VectorXd z0 = s.shooting.z_from_unknowns(s.newton.q);
    DarkMeasures m = measure_dark_breather(j.params, z0, j.omega_b, s.shooting.integration());
    FloquetResult f;
    if (floquet) {
      Eigen::VectorXd r;
      Eigen::MatrixXd J, A;
      if (full_monodromy || j.mode == ShootingMode::full) {
        DarkShooting full(j.params, j.sites, j.center, ShootingMode::full, s.shooting.integration());
        full.evaluate(full.unknowns_from_z(z0), j.omega_b, r, &J, &A);
        f = floquet_from_monodromy(A);
      } else {
        s.shooting.evaluate(s.newton.q, j.omega_b, r, &J, &A);
        f = floquet_reversible(s.shooting, A);
      }
    }
    return std::make_tuple(std::move(s), m, f);
  });
  py::dict d = solution_dict(j, s, m);
  if (floquet) d["floquet"] = floquet_dict(f);
  return d;
}

py::dict continue_job(const Params& p, double omega_b, const std::string& edge, const std::string& center, Index sites,
                      const std::string& mode, double tolerance, Index max_iterations, Index points, double ds,
                      double omega_min, std::optional<double> omega_max, bool floquet) {
  const DarkJob j = make_job(p, omega_b, edge, center, sites, mode, tolerance, max_iterations);
  config::checked_option(double(points), config::dark_points, "points");
  try {
    validate_continuation_window(p, omega_b, ds, omega_min, omega_max);
  } catch (const InvalidParameter& e) {  // the library names CLI options: omega-max -> omega_max
    std::string name = e.parameter(), text = e.what();
    std::replace(name.begin(), name.end(), '-', '_');
    throw InvalidParameter(name, text.substr(text.find(": ") + 2));
  }
  check_job_memory(j, floquet, 0);
  InterruptGuard guard;
  BranchResult br = guard.run([&] {
    Solved s = solve(j, guard.flag());
    require_converged(j, s.newton);
    ContinuationOptions o;
    o.stop = guard.flag();
    o.max_points = points;
    o.ds = ds;
    o.omega_min = omega_min;
    o.omega_max = omega_max ? *omega_max : s.ansatz.omega;
    o.floquet = floquet;
    o.tolerance = j.tolerance;
    return continue_branch(s.shooting, s.newton.q, j.omega_b, o);
  });
  const py::ssize_t k = static_cast<py::ssize_t>(br.points.size()), N = j.sites;
  py::array_t<double> omega(k), tangent(k), residual(k);
  py::array_t<int> iterations(k);
  py::array_t<double> x({k, N}), y({k, N});
  py::list measure_rows, floquet_rows;
  for (py::ssize_t i = 0; i < k; ++i) {
    const BranchPoint& b = br.points[static_cast<std::size_t>(i)];
    omega.mutable_at(i) = b.omega_b;
    tangent.mutable_at(i) = b.tangent_omega;
    residual.mutable_at(i) = b.residual;
    iterations.mutable_at(i) = static_cast<int>(b.iterations);  // int32, as in the HDF5 file
    for (py::ssize_t n = 0; n < N; ++n) {
      x.mutable_at(i, n) = b.z0(n);
      y.mutable_at(i, n) = b.z0(N + n);
    }
    measure_rows.append(measures(b.measures));
    floquet_rows.append(floquet ? py::object(floquet_dict(b.floquet)) : py::object(py::none()));
  }
  py::dict d;
  d["omega_b"] = omega;
  d["tangent_omega"] = tangent;
  d["residual"] = residual;
  d["iterations"] = iterations;
  d["x"] = x;
  d["y"] = y;
  d["measures"] = measure_rows;
  d["floquet"] = floquet_rows;
  d["turning_points"] = br.turning_points;
  d["stop_reason"] = br.stop_reason;
  return d;
}

py::dict evolve_job(const Params& p, double omega_b, const std::string& edge, const std::string& center, Index sites,
                    const std::string& mode, double tolerance, Index max_iterations, double t_end, Index samples) {
  const DarkJob j = make_job(p, omega_b, edge, center, sites, mode, tolerance, max_iterations);
  const double period = 2 * std::numbers::pi / omega_b;
  if (!(std::isfinite(t_end) && t_end >= period))
    throw InvalidParameter("t_end", "must be a finite time of at least one period T_b = 2 pi/omega_b (dimensionless "
                                    "time of Sec. 2)");
  config::checked_option_count(t_end, period, config::dark_periods, "t_end");
  config::checked_option(double(samples), config::dark_samples, "samples");
  check_job_memory(j, false, std::floor(t_end / period));
  InterruptGuard guard;
  DarkEvolution e = guard.run([&] {
    Solved s = solve(j, guard.flag());
    require_converged(j, s.newton);
    const Eigen::VectorXd z0 = s.shooting.z_from_unknowns(s.newton.q);
    return evolve_dark_breather(j.params, z0, j.omega_b, t_end, samples, s.shooting.integration(), guard.flag());
  });
  const py::ssize_t N = e.sites;
  const py::ssize_t rows = static_cast<py::ssize_t>(e.snapshots.size());
  py::array_t<double> x({rows, N}), y({rows, N});
  for (py::ssize_t m = 0; m < rows; ++m)
    for (py::ssize_t n = 0; n < N; ++n) {
      x.mutable_at(m, n) = e.snapshots[static_cast<std::size_t>(m)](n);
      y.mutable_at(m, n) = e.snapshots[static_cast<std::size_t>(m)](N + n);
    }
  py::dict d = evolution_series(e);
  d["x"] = x;
  d["y"] = y;
  return d;
}

}  // namespace

void register_dark(py::module_& m) {
  m.def("dark_solve", &solve_job, py::arg("params"), py::arg("omega_b"), py::arg("branch"), py::arg("center"),
        py::arg("sites"), py::arg("mode"), py::arg("tolerance"), py::arg("max_iterations"), py::arg("floquet"),
        py::arg("full_monodromy"));
  m.def("dark_continue", &continue_job, py::arg("params"), py::arg("omega_b"), py::arg("branch"),
        py::arg("center"), py::arg("sites"), py::arg("mode"), py::arg("tolerance"), py::arg("max_iterations"),
        py::arg("points"), py::arg("ds"), py::arg("omega_min"), py::arg("omega_max"), py::arg("floquet"));
  m.def("dark_evolve", &evolve_job, py::arg("params"), py::arg("omega_b"), py::arg("branch"), py::arg("center"),
        py::arg("sites"), py::arg("mode"), py::arg("tolerance"), py::arg("max_iterations"), py::arg("t_end"),
        py::arg("samples"));
}

}  // namespace lrchain::python

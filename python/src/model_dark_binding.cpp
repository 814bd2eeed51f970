// lrchain.dark.solve|floquet|continue_branch|evolve(model=...): exact dark breathers of any model file
// on its generated lattice code (sim/dark/model_shooting.hpp, model_dark_ansatz.hpp), with the checks
// of `lrchain dark ... --model FILE`; run without the GIL, Ctrl-C raises KeyboardInterrupt.
#include <cmath>
#include <fmt/format.h>
#include <numbers>
#include <optional>
#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "dark_arrays.hpp"
#include "interrupt_guard.hpp"
#include "loaded_model.hpp"
#include "lrchain/config/option_caps.hpp"
#include "lrchain/errors.hpp"
#include "lrchain/sim/dark/continuation.hpp"
#include "lrchain/sim/dark/evolution.hpp"
#include "lrchain/sim/dark/model_dark_ansatz.hpp"
#include "lrchain/sim/dark/model_shooting.hpp"
#include "lrchain/sim/model_lattice_bloch.hpp"
#include "lrchain/sim/resource_estimate.hpp"

namespace py = pybind11;

namespace lrchain::python {

namespace {
using namespace lrchain::sim::dark;

// A model's dark job after its checks: the seed's coefficients at the defocusing edge.
struct ModelDarkJob {
  const LoadedModel* loaded;
  const lrchain_lattice_kernels* kernels;
  ModelDarkAnsatz ansatz;
  double omega_b;
  DarkCenter center;
  Index sites;
  ShootingMode mode;
  double tolerance;
  Index max_iterations;
  ContactBonds contacts = {};  // one-sided contacts in the lattice form's variables (empty: a smooth model)
};

// The checks of `lrchain dark ... --model` (edge, omega_b, sites, Newton, memory) before anything runs;
// `periods`: the evolution's periods (0 for the other jobs), for the memory estimate.
ModelDarkJob make_job(const LoadedModel& loaded, double omega_b, const std::optional<std::string>& branch,
                      const std::string& center, Index sites, const std::string& mode, double tolerance,
                      Index max_iterations, double periods) {
  const DarkCenter c = parse_dark_center(center);
  const ShootingMode m = parse_shooting_mode(mode);
  const lrchain_lattice_kernels& kernels = lattice_kernels(loaded);
  const std::optional<Index> given = branch ? std::optional(loaded.model.branch(*branch)) : std::nullopt;
  ModelDarkJob j{&loaded, &kernels, {}, omega_b, c, sites, m, tolerance, max_iterations};
  try {
    j.ansatz = make_model_dark_ansatz(loaded.model, kernels, defocusing_edge(loaded.model, given), omega_b);
  } catch (const InvalidParameter& e) {  // the library names CLI options: omega-b -> omega_b
    if (e.parameter() != "omega-b") throw;
    const std::string text = e.what();
    throw InvalidParameter("omega_b", text.substr(text.find(": ") + 2));
  }
  config::checked_option(double(sites), config::dark_sites, "sites");
  check_dark_sites(j.ansatz, sites);
  j.contacts = model_contact_bonds(kernels, sim::lattice_parameters(loaded.model), j.ansatz.mean_flow);
  if (!(tolerance > 0 && tolerance < 1)) throw InvalidParameter("tolerance", "must be in (0, 1)");
  if (max_iterations < 1) throw InvalidParameter("max_iterations", "must be an integer >= 1");
  // The estimate counts two fields per site: scale the sites to the model's number of fields.
  const sim::ResourceEstimate e =
      sim::estimate_dark_breather(double(sites) * double(kernels.fields) / 2.0, true, 2 * std::numbers::pi / omega_b, periods);
  sim::check_memory(e, 0, e.dominant == "periods" ? "t_end" : "sites", e.dominant == "periods" ? "lower t_end" : "lower sites");
  return j;
}

ModelDarkShooting make_shooting(const ModelDarkJob& j, const std::atomic<bool>* stop) {
  ContactIntegrationOptions integration;
  integration.stop = stop;
  return ModelDarkShooting(*j.kernels, sim::lattice_parameters(j.loaded->model), j.sites, j.ansatz.mean_flow, j.mode,
                           integration, j.contacts);
}

// Newton from the model's seed (without the GIL); NumericalFailure with the history if it fails.
NewtonResult solve(const ModelDarkJob& j, const ModelDarkShooting& shooting, const Eigen::VectorXd& seed,
                   const std::atomic<bool>* stop) {
  NewtonOptions o;
  o.tolerance = j.tolerance;
  o.max_iterations = j.max_iterations;
  o.progress = [stop](const NewtonRecord&) {
    if (stop->load(std::memory_order_relaxed)) throw Interrupted(SIGINT, "interrupted by SIGINT");
  };
  NewtonResult r = newton_solve(shooting, seed, j.omega_b, o);
  if (!r.converged) throw NumericalFailure(sim::dark::newton_failure_message(r, j.omega_b));
  return r;
}

// (fields, sites) array of a field-major vector of positions.
py::array_t<double> by_field(const Eigen::VectorXd& z, Index fields, Index sites) {
  py::array_t<double> a({py::ssize_t(fields), py::ssize_t(sites)});
  std::copy(z.data(), z.data() + z.size(), a.mutable_data());
  return a;
}

// What every model job reports: the edge, the seed's coefficients, the lattice variables.
py::dict job_dict(const ModelDarkJob& j) {
  const int fields = j.kernels->fields;
  py::list variables;
  for (int f = 0; f < fields; ++f)
    variables.append(j.ansatz.mean_flow ? (f == 0 ? std::string("r") : fmt::format("w{}", f)) : fmt::format("u{}", f));
  py::array_t<double> n(j.sites);
  for (Index i = 0; i < j.sites; ++i) n.mutable_at(i) = i - (j.sites - 1) / 2;
  py::dict d;
  d["model"] = py::module_::import("json").attr("loads")(model_summary_json(*j.loaded).dump());
  d["branch"] = j.loaded->definition->branch_names.at(j.ansatz.branch);
  d["theta"] = j.ansatz.theta;
  d["omega_edge"] = j.ansatz.omega;
  d["curvature"] = j.ansatz.curvature;
  d["h_tilde"] = j.ansatz.h_tilde;
  d["lambda"] = j.ansatz.mean_flow ? py::object(py::float_(j.ansatz.lambda)) : py::object(py::none());
  d["lattice_form"] = j.ansatz.mean_flow ? "strain" : "displacement";
  d["variables"] = py::tuple(variables);
  d["n"] = n;
  py::list contacts;
  for (const auto& bond : j.contacts) contacts.append(bond.name);
  d["one_sided_contacts"] = py::tuple(contacts);
  return d;
}

// The measures; K_y, C_y are None where the lattice has no second strain-form variable (as the CLI).
py::dict model_measures(const ModelDarkJob& j, const DarkMeasures& m) {
  py::dict d = measures(m);
  if (!j.ansatz.mean_flow || j.kernels->fields < 2) {
    d["K_y"] = py::none();
    d["C_y"] = py::none();
  }
  return d;
}

py::dict solve_job(const LoadedModel& loaded, double omega_b, std::optional<std::string> branch, const std::string& center,
                   Index sites, const std::string& mode, double tolerance, Index max_iterations, bool floquet) {
  const ModelDarkJob j = make_job(loaded, omega_b, branch, center, sites, mode, tolerance, max_iterations, 0);
  const Eigen::VectorXd seed = model_dark_seed(j.ansatz, j.center, j.sites);
  InterruptGuard guard;
  auto [newton, m, f, changes] = guard.run([&] {
    const ModelDarkShooting shooting = make_shooting(j, guard.flag());
    NewtonResult r = solve(j, shooting, seed, guard.flag());
    const std::optional<Index> changes = shooting.contact_changes_per_period(r.q, j.omega_b);
    DarkMeasures m;
    shooting.measure(r.q, j.omega_b, m);
    FloquetResult f;
    if (floquet) f = floquet_from_monodromy(shooting.monodromy(r.q, j.omega_b));
    return std::make_tuple(std::move(r), m, f, changes);
  });
  py::dict d = job_dict(j);
  d["z"] = by_field(newton.q, j.kernels->fields, j.sites);
  d["seed"] = by_field(seed, j.kernels->fields, j.sites);
  d["newton_residuals"] = residuals(newton);
  d["measures"] = model_measures(j, m);
  d["floquet"] = floquet ? py::object(floquet_dict(f)) : py::object(py::none());
  d["contact_changes_per_period"] = changes ? py::object(py::int_(*changes)) : py::object(py::none());
  return d;
}

// Solve, then continue away from the edge as `lrchain dark continue --model` does: into the gap
// (omega_b falling) below an edge, rising above one (h_tilde > 0), within [omega_min, omega_max].
py::dict continue_job(const LoadedModel& loaded, double omega_b, std::optional<std::string> branch,
                      const std::string& center, Index sites, const std::string& mode, double tolerance,
                      Index max_iterations, Index points, double ds, double omega_min, std::optional<double> omega_max,
                      bool floquet) {
  const ModelDarkJob j = make_job(loaded, omega_b, branch, center, sites, mode, tolerance, max_iterations, 0);
  config::checked_option(double(points), config::dark_points, "points");
  if (!(std::isfinite(ds) && ds > 0 && ds <= 1)) throw InvalidParameter("ds", "must be in (0, 1] (it adapts within [1e-5, 1])");
  if (!std::isfinite(omega_min) || !(omega_min < omega_b)) throw InvalidParameter("omega_min", "must be a finite number below omega_b");
  if (omega_max && !(std::isfinite(*omega_max) && *omega_max > omega_b))
    throw InvalidParameter("omega_max", "must be None (the band edge, or none above it) or a frequency above omega_b");
  const Eigen::VectorXd seed = model_dark_seed(j.ansatz, j.center, j.sites);
  InterruptGuard guard;
  const double edge = j.ansatz.omega;
  const BranchResult br = guard.run([&] {
    const ModelDarkShooting shooting = make_shooting(j, guard.flag());
    const NewtonResult r = solve(j, shooting, seed, guard.flag());
    ContinuationOptions o;
    o.stop = guard.flag();
    o.max_points = points;
    o.ds = ds;
    o.floquet = floquet;
    o.tolerance = j.tolerance;
    const bool above = omega_b > edge;  // an edge with h_tilde > 0: the branch rises from it
    o.direction = above ? 1.0 : -1.0;
    o.omega_min = above ? std::max(omega_min, edge) : omega_min;
    o.omega_max = omega_max ? *omega_max : above ? 1e300 : edge;
    return continue_branch(shooting, r.q, j.omega_b, o);
  });
  const py::ssize_t k = py::ssize_t(br.points.size()), fields = j.kernels->fields, N = j.sites;
  py::array_t<double> omega(k), tangent(k), residual(k);
  py::array_t<int> iterations(k);
  py::array_t<double> z({k, fields, N});
  py::list measure_rows, floquet_rows, contact_rows;
  for (py::ssize_t i = 0; i < k; ++i) {
    const BranchPoint& b = br.points[std::size_t(i)];
    omega.mutable_at(i) = b.omega_b;
    tangent.mutable_at(i) = b.tangent_omega;
    residual.mutable_at(i) = b.residual;
    iterations.mutable_at(i) = static_cast<int>(b.iterations);  // int32, as in the HDF5 file
    std::copy(b.z0.data(), b.z0.data() + fields * N, z.mutable_data(i, 0, 0));
    measure_rows.append(model_measures(j, b.measures));
    floquet_rows.append(floquet ? py::object(floquet_dict(b.floquet)) : py::object(py::none()));
    contact_rows.append(b.contact_changes_per_period ? py::object(py::int_(*b.contact_changes_per_period))
                                                     : py::object(py::none()));
  }
  py::dict d = job_dict(j);
  d["omega_b"] = omega;
  d["tangent_omega"] = tangent;
  d["residual"] = residual;
  d["iterations"] = iterations;
  d["z"] = z;
  d["measures"] = measure_rows;
  d["floquet"] = floquet_rows;
  d["contact_changes_per_period"] = contact_rows;
  d["turning_points"] = br.turning_points;
  d["stop_reason"] = br.stop_reason;
  return d;
}

// Solve, then integrate from Z(0) over floor(t_end / T_b) periods (`lrchain dark evolve --model`).
py::dict evolve_job(const LoadedModel& loaded, double omega_b, std::optional<std::string> branch, const std::string& center,
                    Index sites, const std::string& mode, double tolerance, Index max_iterations, double t_end, Index samples) {
  const double period = 2 * std::numbers::pi / omega_b;
  if (!(std::isfinite(t_end) && std::isfinite(period) && t_end >= period))
    throw InvalidParameter("t_end", fmt::format("must be a finite time of at least one period T_b = 2 pi/omega_b = {:.6g}", period));
  config::checked_option_count(t_end, period, config::dark_periods, "t_end");
  config::checked_option(double(samples), config::dark_samples, "samples");
  const ModelDarkJob j = make_job(loaded, omega_b, branch, center, sites, mode, tolerance, max_iterations,
                                  std::floor(t_end / period));
  const Eigen::VectorXd seed = model_dark_seed(j.ansatz, j.center, j.sites);
  InterruptGuard guard;
  const DarkEvolution e = guard.run([&] {
    const ModelDarkShooting shooting = make_shooting(j, guard.flag());
    const NewtonResult r = solve(j, shooting, seed, guard.flag());
    return evolve_dark_orbit(shooting.advance(), r.q, j.sites, j.omega_b, t_end, samples, guard.flag());
  });
  const py::ssize_t fields = j.kernels->fields, N = j.sites;
  const py::ssize_t rows = py::ssize_t(e.snapshots.size());
  py::array_t<double> z({rows, fields, N});
  for (py::ssize_t m = 0; m < rows; ++m)
    std::copy(e.snapshots[std::size_t(m)].data(), e.snapshots[std::size_t(m)].data() + fields * N, z.mutable_data(m, 0, 0));
  py::dict d = job_dict(j);
  for (const auto& [key, value] : evolution_series(e)) d[key] = value;
  d["z"] = z;
  return d;
}

}  // namespace

void register_model_dark(py::module_& m) {
  m.def("dark_model_solve", &solve_job, py::arg("model"), py::arg("omega_b"), py::arg("branch"), py::arg("center"),
        py::arg("sites"), py::arg("mode"), py::arg("tolerance"), py::arg("max_iterations"), py::arg("floquet"));
  m.def("dark_model_continue", &continue_job, py::arg("model"), py::arg("omega_b"), py::arg("branch"),
        py::arg("center"), py::arg("sites"), py::arg("mode"), py::arg("tolerance"), py::arg("max_iterations"),
        py::arg("points"), py::arg("ds"), py::arg("omega_min"), py::arg("omega_max"), py::arg("floquet"));
  m.def("dark_model_evolve", &evolve_job, py::arg("model"), py::arg("omega_b"), py::arg("branch"), py::arg("center"),
        py::arg("sites"), py::arg("mode"), py::arg("tolerance"), py::arg("max_iterations"), py::arg("t_end"),
        py::arg("samples"));
}

}  // namespace lrchain::python

// lrchain.dark.solve|floquet|continue_branch|evolve(model=...): exact dark breathers of any model file
// by the dark job (lrchain/jobs/dark_job.hpp) on the model's generated lattice code; run without the
// GIL, Ctrl-C raises KeyboardInterrupt. Results as numpy arrays.
#include <algorithm>
#include <optional>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "dark_arrays.hpp"
#include "dark_job_binding.hpp"
#include "loaded_model.hpp"

namespace py = pybind11;

namespace lrchain::python {

namespace {
using namespace lrchain::jobs::dark;

// The options of a model's job; the model's lattice kernels are loaded here (with the GIL held).
DarkConfig model_config(DarkStep step, const LoadedModel& loaded, double omega_b, const std::optional<std::string>& branch,
                        const std::string& center, std::optional<double> sites, const std::string& mode, double tolerance,
                        double max_iterations) {
  DarkConfig c = dark_config(step, omega_b, branch, center, sites, mode, tolerance, max_iterations);
  c.model = &loaded.model;
  c.kernels = &lattice_kernels(loaded);
  return c;
}

// (rows..., fields, sites) array of field-major vectors of positions.
py::array_t<double> by_field(const std::vector<const Eigen::VectorXd*>& rows, Index fields, Index sites, bool one) {
  std::vector<py::ssize_t> shape{py::ssize_t(fields), py::ssize_t(sites)};
  if (!one) shape.insert(shape.begin(), py::ssize_t(rows.size()));
  py::array_t<double> a(shape);
  double* at = a.mutable_data();
  for (const Eigen::VectorXd* z : rows) at = std::copy(z->data(), z->data() + fields * sites, at);
  return a;
}

// What every model job reports: the edge, the seed's coefficients, the lattice variables.
py::dict edge_dict(const LoadedModel& loaded, const DarkResult& r) {
  const DarkEdge& e = r.edge;
  const Index sites = dark_sites(r.config);
  py::array_t<double> n(sites);
  for (Index i = 0; i < sites; ++i) n.mutable_at(i) = i - (sites - 1) / 2;
  py::dict d;
  d["model"] = py::module_::import("json").attr("loads")(model_summary_json(loaded).dump());
  d["branch"] = e.branch;
  d["theta"] = e.theta;
  d["omega_edge"] = e.omega;
  d["curvature"] = e.curvature;
  d["h_tilde"] = e.h_tilde;
  d["lambda"] = e.mean_flow ? py::object(py::float_(e.lambda)) : py::object(py::none());
  d["lattice_form"] = e.mean_flow ? "strain" : "displacement";
  d["variables"] = py::tuple(py::cast(e.variables));
  d["n"] = n;
  d["one_sided_contacts"] = py::tuple(py::cast(e.one_sided_contacts));
  return d;
}

// The measures; K_y, C_y are None where the lattice has no second strain-form variable (as the CLI).
py::dict model_measures(const DarkEdge& e, const sim::dark::DarkMeasures& m) {
  py::dict d = measures(m);
  if (!e.mean_flow || e.fields < 2) {
    d["K_y"] = py::none();
    d["C_y"] = py::none();
  }
  return d;
}

py::object count_or_none(const std::optional<Index>& count) {
  return count ? py::object(py::int_(*count)) : py::object(py::none());
}

py::dict model_dark_solve_job(const LoadedModel& loaded, double omega_b, std::optional<std::string> branch, const std::string& center,
                   std::optional<double> sites, const std::string& mode, double tolerance, double max_iterations, bool floquet) {
  const DarkConfig c = model_config(floquet ? DarkStep::floquet : DarkStep::solve, loaded, omega_b, branch, center,
                                    sites, mode, tolerance, max_iterations);
  const DarkResult r = run_dark_job(c);
  py::dict d = edge_dict(loaded, r);
  d["z"] = by_field({&r.z0}, r.edge.fields, dark_sites(r.config), true);
  d["seed"] = by_field({&r.seed}, r.edge.fields, dark_sites(r.config), true);
  d["newton_residuals"] = residuals(r.newton);
  d["measures"] = model_measures(r.edge, r.measures);
  d["floquet"] = floquet ? py::object(floquet_dict(*r.floquet)) : py::object(py::none());
  d["contact_changes_per_period"] = count_or_none(r.contact_changes_per_period);
  return d;
}

// Solve, then continue away from the edge as `lrchain dark continue --model` does: into the gap
// (omega_b falling) below an edge, rising above one (h > 0), within [omega_min, omega_max].
py::dict continue_job(const LoadedModel& loaded, double omega_b, std::optional<std::string> branch,
                      const std::string& center, std::optional<double> sites, const std::string& mode, double tolerance,
                      double max_iterations, double points, double ds, double omega_min, std::optional<double> omega_max,
                      bool floquet, const std::string& parameter, std::optional<double> to, const py::object& progress) {
  DarkConfig c = model_config(DarkStep::branch, loaded, omega_b, branch, center, sites, mode, tolerance, max_iterations);
  set_branch_keywords(c, points, ds, omega_min, omega_max, floquet, parameter, to);
  const DarkResult r = run_dark_job(c, progress);
  const DarkEdge& e = r.edge;
  py::dict d = edge_dict(loaded, r);
  for (const auto& [key, value] :
       branch_arrays(r.branch, floquet, [&e](const sim::dark::DarkMeasures& m) { return model_measures(e, m); }))
    d[key] = value;
  std::vector<const Eigen::VectorXd*> rows;
  py::list contact_rows;
  for (const auto& b : r.branch.points) {
    rows.push_back(&b.z0);
    contact_rows.append(count_or_none(b.contact_changes_per_period));
  }
  d["z"] = by_field(rows, e.fields, dark_sites(r.config), false);
  d["contact_changes_per_period"] = contact_rows;
  py::list values;  // the continued parameter's value at each point (omega_b when continuing in omega_b)
  for (const auto& b : r.branch.points) values.append(b.parameter);
  d["parameter"] = c.parameter;
  d["parameter_values"] = values;
  return d;
}

// Solve, then integrate from Z(0) over floor(t_end / T_b) periods (`lrchain dark evolve --model`).
py::dict evolve_job(const LoadedModel& loaded, double omega_b, std::optional<std::string> branch, const std::string& center,
                    std::optional<double> sites, const std::string& mode, double tolerance, double max_iterations, double t_end,
                    double samples, const std::string& perturb, double perturb_size, double seed,
                    const py::object& progress) {
  DarkConfig c = model_config(DarkStep::evolve, loaded, omega_b, branch, center, sites, mode, tolerance, max_iterations);
  set_evolve_keywords(c, t_end, samples, perturb, perturb_size, seed);
  const DarkResult r = run_dark_job(c, progress);
  std::vector<const Eigen::VectorXd*> rows;
  for (const auto& z : r.evolution.snapshots) rows.push_back(&z);
  py::dict d = edge_dict(loaded, r);
  for (const auto& [key, value] : evolution_series(r.evolution)) d[key] = value;
  d["z"] = by_field(rows, r.edge.fields, dark_sites(r.config), false);
  return d;
}

}  // namespace

void register_model_dark(py::module_& m) {
  m.def("dark_model_solve", &model_dark_solve_job, py::arg("model"), py::arg("omega_b"), py::arg("branch"), py::arg("center"),
        py::arg("sites"), py::arg("mode"), py::arg("tolerance"), py::arg("max_iterations"), py::arg("floquet"));
  m.def("dark_model_continue", &continue_job, py::arg("model"), py::arg("omega_b"), py::arg("branch"),
        py::arg("center"), py::arg("sites"), py::arg("mode"), py::arg("tolerance"), py::arg("max_iterations"),
        py::arg("points"), py::arg("ds"), py::arg("omega_min"), py::arg("omega_max"), py::arg("floquet"), py::arg("parameter"), py::arg("to"),
        py::arg("progress") = py::none());
  m.def("dark_model_evolve", &evolve_job, py::arg("model"), py::arg("omega_b"), py::arg("branch"), py::arg("center"),
        py::arg("sites"), py::arg("mode"), py::arg("tolerance"), py::arg("max_iterations"), py::arg("t_end"),
        py::arg("samples"), py::arg("perturb"), py::arg("perturb_size"), py::arg("seed"), py::arg("progress") = py::none());
}

}  // namespace lrchain::python

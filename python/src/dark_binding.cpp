// lrchain.dark on the resonant chain: exact stationary dark breathers (Sec. 5.3-5.4) by the dark
// job (lrchain/jobs/dark_job.hpp), run without the GIL; its results as numpy arrays.
#include <optional>
#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "dark_arrays.hpp"
#include "dark_job_binding.hpp"
#include "lrchain/jobs/dark_schema.hpp"

namespace py = pybind11;

namespace lrchain::python {

namespace {
using namespace lrchain::jobs::dark;

DarkConfig chain_config(DarkStep step, const Params& p, double omega_b, const std::string& branch,
                        const std::string& center, std::optional<double> sites, const std::string& mode, double tolerance,
                        double max_iterations) {
  DarkConfig c = dark_config(step, omega_b, branch, center, sites, mode, tolerance, max_iterations);
  c.params = p;
  return c;
}

// The solution as a dict: profile x_n(0), y_n(0), the seed, Newton's history, the measures (Sec. 5.3).
py::dict solve_job(const Params& p, double omega_b, const std::string& branch, const std::string& center, std::optional<double> sites,
                   const std::string& mode, double tolerance, double max_iterations, bool floquet, bool full_monodromy) {
  DarkConfig c = chain_config(floquet ? DarkStep::floquet : DarkStep::solve, p, omega_b, branch, center, sites, mode,
                              tolerance, max_iterations);
  c.full_monodromy = full_monodromy;
  const DarkResult r = run_dark_job(c);
  const Index N = dark_sites(r.config);
  py::array_t<double> n(N);
  for (Index i = 0; i < N; ++i) n.mutable_at(i) = i - (N - 1) / 2;
  py::dict d;
  d["n"] = n;
  d["x"] = Eigen::VectorXd(r.z0.head(N));
  d["y"] = Eigen::VectorXd(r.z0.tail(N));
  d["x_seed"] = Eigen::VectorXd(r.seed.head(N));
  d["y_seed"] = Eigen::VectorXd(r.seed.tail(N));
  d["newton_residuals"] = residuals(r.newton);
  d["omega_edge"] = r.edge.omega;
  d["measures"] = measures(r.measures);
  if (floquet) d["floquet"] = floquet_dict(*r.floquet);
  return d;
}

py::dict continue_job(const Params& p, double omega_b, const std::string& branch, const std::string& center, std::optional<double> sites,
                      const std::string& mode, double tolerance, double max_iterations, double points, double ds,
                      double omega_min, std::optional<double> omega_max, bool floquet, const std::string& parameter,
                      std::optional<double> to, const py::object& progress) {
  DarkConfig c = chain_config(DarkStep::branch, p, omega_b, branch, center, sites, mode, tolerance, max_iterations);
  set_branch_keywords(c, points, ds, omega_min, omega_max, floquet, parameter, to);
  const DarkResult r = run_dark_job(c, progress);
  py::dict d = branch_arrays(r.branch, floquet, [](const sim::dark::DarkMeasures& m) { return measures(m); });
  // x, y: (points, sites) profiles Z(0) of the two fields
  const py::ssize_t k = static_cast<py::ssize_t>(r.branch.points.size()), N = dark_sites(r.config);
  py::array_t<double> x({k, N}), y({k, N});
  for (py::ssize_t i = 0; i < k; ++i)
    for (py::ssize_t n = 0; n < N; ++n) {
      x.mutable_at(i, n) = r.branch.points[std::size_t(i)].z0(n);
      y.mutable_at(i, n) = r.branch.points[std::size_t(i)].z0(N + n);
    }
  d["x"] = x;
  d["y"] = y;
  return d;
}

py::dict evolve_job(const Params& p, double omega_b, const std::string& branch, const std::string& center, std::optional<double> sites,
                    const std::string& mode, double tolerance, double max_iterations, double t_end, double samples,
                    const std::string& perturb, double perturb_size, double seed, const py::object& progress) {
  DarkConfig c = chain_config(DarkStep::evolve, p, omega_b, branch, center, sites, mode, tolerance, max_iterations);
  set_evolve_keywords(c, t_end, samples, perturb, perturb_size, seed);
  const DarkResult r = run_dark_job(c, progress);
  const sim::dark::DarkEvolution& e = r.evolution;
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

// A job's option schema (option_schema.hpp) as a list of dicts: what the Python functions take their
// defaults and docstrings from.
py::list options_schema(const std::vector<jobs::JobOption>& options) {
  const py::object loads = py::module_::import("json").attr("loads");
  py::list out;
  for (const jobs::JobOption& o : options) out.append(loads(jobs::to_json(o).dump()));
  return out;
}

}  // namespace

void register_dark(py::module_& m) {
  m.def("dark_options", [] { return options_schema(dark_options()); },
        "The dark job's options: key, cli, python, steps, default, required, range, doc, help (the CLI's text).");
  m.def("job_options", [](const std::string& job) { return options_schema(jobs::job_options(job)); }, py::arg("job"),
        "A job's options (\"bright\", \"coeffs\", \"regime map\", ...; job_names()): key, cli, python, steps, "
        "default, required, range, doc, help (the CLI's text), default_text.");
  m.def("job_names", &jobs::job_names, "The jobs that have an option schema (job_options).");
  m.def("dark_solve", &solve_job, py::arg("params"), py::arg("omega_b"), py::arg("branch"), py::arg("center"),
        py::arg("sites"), py::arg("mode"), py::arg("tolerance"), py::arg("max_iterations"), py::arg("floquet"),
        py::arg("full_monodromy"));
  m.def("dark_continue", &continue_job, py::arg("params"), py::arg("omega_b"), py::arg("branch"),
        py::arg("center"), py::arg("sites"), py::arg("mode"), py::arg("tolerance"), py::arg("max_iterations"),
        py::arg("points"), py::arg("ds"), py::arg("omega_min"), py::arg("omega_max"), py::arg("floquet"), py::arg("parameter"), py::arg("to"),
        py::arg("progress") = py::none());
  m.def("dark_evolve", &evolve_job, py::arg("params"), py::arg("omega_b"), py::arg("branch"), py::arg("center"),
        py::arg("sites"), py::arg("mode"), py::arg("tolerance"), py::arg("max_iterations"), py::arg("t_end"),
        py::arg("samples"), py::arg("perturb"), py::arg("perturb_size"), py::arg("seed"), py::arg("progress") = py::none());
}

}  // namespace lrchain::python

// lrchain.bright.solve|floquet|continue_branch|evolve(model, ...): exact bright breathers of any model by the bright-breather
// job (lrchain/jobs/bright_breather_job.hpp), run without the GIL (Ctrl-C: KeyboardInterrupt after the
// current Newton step). The result as the job's JSON summary (a dict) with Z(0) and the seed as numpy
// arrays (fields, sites).
#include <algorithm>
#include <csignal>
#include <cstdint>
#include <optional>
#include <vector>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "dark_job_binding.hpp"
#include "interrupt_guard.hpp"
#include "loaded_model.hpp"
#include "lrchain/config/option_caps.hpp"
#include "lrchain/jobs/bright_breather_job.hpp"
#include "lrchain/jobs/bright_breather_schema.hpp"

namespace py = pybind11;

namespace lrchain::python {

namespace {
using namespace lrchain::jobs::bright_breather;

// (fields, sites) array of a field-major vector.
py::array_t<double> by_field(const Eigen::VectorXd& z, Index fields, Index sites) {
  py::array_t<double> a({py::ssize_t(fields), py::ssize_t(sites)});
  std::copy(z.data(), z.data() + z.size(), a.mutable_data());
  return a;
}

py::dict bright_solve_job(const LoadedModel& loaded, double omega_b, const std::optional<std::string>& branch,
                   const std::string& center, double sites, double tolerance, double max_iterations,
                   double tail_tolerance, double unit_tolerance, const std::string& step, double points, double ds,
                   bool branch_floquet, double periods, const std::string& perturb, double perturb_size,
                   std::uint64_t seed, const std::string& parameter, std::optional<double> to,
                   double locate_tolerance, const std::string& start, const std::string& coupling) {
  BrightBreatherConfig c;
  c.step = step == "continue"  ? BrightStep::branch
           : step == "floquet" ? BrightStep::floquet
           : step == "evolve"  ? BrightStep::evolve
                               : BrightStep::solve;
  c.periods = integer_keyword(periods, "periods", 1, 1'000'000);
  c.perturb = perturb;
  c.perturb_size = perturb_size;
  c.seed = seed;
  c.parameter = parameter;
  c.to = to;
  c.points = integer_keyword(points, "points", config::dark_points.least, config::dark_points.most);
  c.ds = ds;
  c.locate_tolerance = locate_tolerance;
  c.branch_floquet = branch_floquet;
  c.model = &loaded.model;
  c.kernels = &lattice_kernels(loaded);
  c.omega_b = omega_b;
  c.branch = branch.value_or("");
  c.center = center;
  c.start = start;
  c.coupling = coupling;
  c.sites = integer_keyword(sites, "sites", config::dark_sites.least, config::dark_sites.most);
  c.tolerance = tolerance;
  c.max_iterations = integer_keyword(max_iterations, "max_iterations", 1, config::int32_most);
  c.tail_tolerance = tail_tolerance;
  c.unit_tolerance = unit_tolerance;
  validate(c);
  InterruptGuard guard;
  BrightBreatherHooks hooks;
  hooks.newton_progress = [stop = guard.flag()](const sim::dark::NewtonRecord&) {
    if (stop->load(std::memory_order_relaxed)) throw Interrupted(SIGINT, "interrupted by SIGINT");
  };
  const BrightBreatherResult r = guard.run([&] { return run(c, hooks); });
  if (const auto message = failure(r)) throw NumericalFailure(*message);
  nlohmann::json j = to_json(r);
  j["model"] = model_summary_json(loaded);
  py::dict d = py::module_::import("json").attr("loads")(j.dump());
  d["z"] = by_field(r.z0, r.edge.fields, c.sites);
  d["seed"] = by_field(r.seed, r.edge.fields, c.sites);
  d["variables"] = py::tuple(py::cast(r.edge.variables));
  if (c.step == BrightStep::branch) {  // Z(0) of every branch point: (points, fields, sites)
    py::array_t<double> z({py::ssize_t(r.branch.points.size()), py::ssize_t(r.edge.fields), py::ssize_t(c.sites)});
    double* at = z.mutable_data();
    for (const auto& p : r.branch.points) at = std::copy(p.z0.data(), p.z0.data() + p.z0.size(), at);
    d["branch_z"] = z;
  }
  if (r.evolution) {  // per period m = 0..periods: t, deviation, energy
    std::vector<double> t, deviation, energy;
    for (const auto& sample : r.evolution->samples)
      t.push_back(sample.t), deviation.push_back(sample.deviation), energy.push_back(sample.energy);
    d["evolution_t"] = py::array_t<double>(py::ssize_t(t.size()), t.data());
    d["evolution_deviation"] = py::array_t<double>(py::ssize_t(deviation.size()), deviation.data());
    d["evolution_energy"] = py::array_t<double>(py::ssize_t(energy.size()), energy.data());
  }
  return d;
}

}  // namespace

void register_bright_breather(py::module_& m) {
  m.def("bright_breather_solve", &bright_solve_job, py::arg("model"), py::arg("omega_b"), py::arg("branch"), py::arg("center"),
        py::arg("sites"), py::arg("tolerance"), py::arg("max_iterations"), py::arg("tail_tolerance"),
        py::arg("unit_tolerance"), py::arg("step"), py::arg("points"), py::arg("ds"), py::arg("branch_floquet"), py::arg("periods"), py::arg("perturb"), py::arg("perturb_size"), py::arg("seed"), py::arg("parameter"), py::arg("to"),
        py::arg("locate_tolerance"), py::arg("start"), py::arg("coupling"));
}

}  // namespace lrchain::python

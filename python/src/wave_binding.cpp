// lrchain.wave.solve|continue_branch|stability|fate(model, ...): exact periodic travelling waves of any model and
// their Floquet-Bloch growth rates by the wave job (lrchain/jobs/wave_job.hpp), run without the GIL. The
// result as the job's JSON summary (a dict) with the profile (fields, 2H+1) and the growth rates as numpy arrays.
#include <algorithm>
#include <optional>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "dark_job_binding.hpp"
#include "interrupt_guard.hpp"
#include "loaded_model.hpp"
#include "lrchain/config/option_caps.hpp"
#include "lrchain/jobs/wave_job.hpp"

namespace py = pybind11;

namespace lrchain::python {

namespace {
using namespace lrchain::jobs::wave;

py::dict wave_job(const LoadedModel& loaded, const std::string& step, const std::string& branch, double theta,
                  double amplitude, double ramp, const std::vector<double>& amplitudes, double harmonics,
                  double max_harmonics, double tail_tolerance, double tolerance, double max_iterations,
                  double k_points, double unstable_tolerance, double ring_sites, double noise, double seed,
                  double periods, double steps_per_period, double modulation) {
  WaveConfig c;
  c.step = step == "continue"    ? WaveStep::branch
           : step == "stability" ? WaveStep::stability
           : step == "fate"      ? WaveStep::fate
           : step == "standing"  ? WaveStep::standing
                                 : WaveStep::solve;
  c.model = &loaded.model;
  c.kernels = &lattice_kernels(loaded);
  c.branch = branch;
  c.theta = theta;
  c.amplitude = amplitude;
  c.ramp = integer_keyword(ramp, "ramp", 1, config::int32_most);
  c.amplitudes = amplitudes;
  c.initial_harmonics = integer_keyword(harmonics, "harmonics", 1, config::int32_most);
  c.max_harmonics = integer_keyword(max_harmonics, "max_harmonics", 1, config::int32_most);
  c.tail_tolerance = tail_tolerance;
  c.tolerance = tolerance;
  c.max_iterations = integer_keyword(max_iterations, "max_iterations", 1, config::int32_most);
  c.k_points = integer_keyword(k_points, "k_points", 1, config::int32_most);
  c.unstable_tolerance = unstable_tolerance;
  c.ring_sites = integer_keyword(ring_sites, "ring_sites", 1, config::int32_most);
  c.noise = noise;
  c.modulation = modulation;
  c.seed = integer_keyword(seed, "seed", 1, config::int32_most);
  c.periods = periods;
  c.steps_per_period = integer_keyword(steps_per_period, "steps_per_period", 1, config::int32_most);
  try {
    validate(c);
  } catch (const InvalidParameter& e) {
    for (const jobs::JobOption& o : wave_options())
      if (o.key == e.parameter() && !o.python.empty()) throw jobs::renamed_parameter(e, o.python);
    throw;
  }
  InterruptGuard guard;
  c.stop = guard.flag();
  const WaveResult r = guard.run([&] { return run(c); });
  if (r.failure && (c.step != WaveStep::branch || r.waves.empty())) throw NumericalFailure(*r.failure);
  nlohmann::json j = to_json(r);
  j["model"] = model_summary_json(loaded);
  py::dict d = py::module_::import("json").attr("loads")(j.dump());
  if (c.step == WaveStep::standing) {  // c_{f,n,k} of the last standing wave: fields x sites x (H+1)
    const auto& s = r.standing.back();
    const Index fields = s.coefficients.rows() / s.sites;
    py::array_t<double> coefficients({py::ssize_t(fields), py::ssize_t(s.sites), py::ssize_t(s.harmonics + 1)});
    double* out = coefficients.mutable_data();
    for (Index row = 0; row < s.coefficients.rows(); ++row)
      for (Index k = 0; k <= s.harmonics; ++k) *out++ = s.coefficients(row, k);
    d["coefficients_array"] = coefficients;
    return d;
  }
  const auto& w = r.waves.back();
  const Index fields = Index(r.mode.kernel.size()), points = 2 * w.harmonics + 1;
  py::array_t<double> profile({py::ssize_t(fields), py::ssize_t(points)});
  std::copy(w.profile.data(), w.profile.data() + w.profile.size(), profile.mutable_data());
  d["profile_array"] = profile;
  return d;
}

}  // namespace

void register_wave(py::module_& m) {
  m.def("wave_job", &wave_job, py::arg("model"), py::arg("step"), py::arg("branch"), py::arg("theta"),
        py::arg("amplitude"), py::arg("ramp"), py::arg("amplitudes"), py::arg("harmonics"), py::arg("max_harmonics"),
        py::arg("tail_tolerance"), py::arg("tolerance"), py::arg("max_iterations"), py::arg("k_points"),
        py::arg("unstable_tolerance"), py::arg("ring_sites"), py::arg("noise"), py::arg("seed"), py::arg("periods"),
        py::arg("steps_per_period"), py::arg("modulation"));
}

}  // namespace lrchain::python

// lrchain.simulate.bright(model=...) and lrchain.simulate.ring: lattice runs of any model file on its
// generated lattice code: the jobs of jobs/simulate/model_simulate_job.hpp, with the checks of
// `lrchain simulate bright|ring --model FILE`, run without the GIL (Ctrl-C raises KeyboardInterrupt
// during the integration; `progress(fraction)` follows it); records as numpy arrays.
#include <nlohmann/json.hpp>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "interrupt_guard.hpp"
#include "progress_hook.hpp"
#include "loaded_model.hpp"
#include "lrchain/errors.hpp"
#include "lrchain/jobs/simulate/model_simulate_job.hpp"
#include "lrchain/sim/strain_sites.hpp"
#include "renamed_options.hpp"
#include "run_options.hpp"
#include "run_record_arrays.hpp"

namespace py = pybind11;

namespace lrchain::python {

namespace {
using namespace lrchain::sim;

// The bright breather of a model (the checks and order of `lrchain simulate bright --model`):
// branch, options, theta on the branch, focusing and detuning, then the run. options: theta,
// detuning, n0, sites (2N + 1), periods, sample_every, dt, ansatz_ends.
py::dict model_bright(const LoadedModel& loaded, const std::string& branch, const py::dict& options,
                      const py::object& progress) {
  const Model& model = loaded.model;
  ModelBrightConfig c;
  std::optional<double> detuning;
  long sites = long(strain_site_count(c.N));
  std::map<std::string, OptionTarget> t{{"theta", &c.theta},   {"detuning", &detuning},
                                        {"n0", &c.n0},         {"sites", &sites},
                                        {"periods", &c.periods}, {"sample_every", &c.sample_every},
                                        {"dt", &c.dt},         {"ansatz_ends", &c.ansatz_ends}};
  assign_options(options, t, "bright", renamed_options("model bright"));
  c.N = strain_half_width(sites, model_bright_sites);
  c.detuning = detuning;
  jobs::prepare(model, c, branch);
  const lrchain_lattice_kernels& kernels = lattice_kernels(loaded);
  const jobs::ModelRunLabel label{model_summary_json(loaded), ""};
  ProgressHook progress_hook(progress);  // `progress(fraction)` or None: the run's share done
  c.progress = progress_hook.hook();
  InterruptGuard guard;  // Ctrl-C: the run stops at its next step boundary, KeyboardInterrupt follows
  const auto report = guard.run([&] { return jobs::simulate_model_bright(model, kernels, c, label, {}, guard.flag()); });
  const ModelBrightResult& r = report.result;
  const nlohmann::json& summary = report.summary;
  py::dict out;
  out["summary_json"] = summary.dump();
  out["record"] = record_arrays(r.record);
  out["fields"] = kernels.fields;
  return out;
}

// Plane waves and a packet on a periodic ring (the checks and order of `lrchain simulate ring`).
// options: theta, amplitudes, sites, periods, steps_per_period, packet_amplitude, packet_width.
py::dict model_ring(const LoadedModel& loaded, const std::string& branch, const py::dict& options,
                    const py::object& progress) {
  const Model& model = loaded.model;
  RingRunConfig c;
  std::map<std::string, OptionTarget> t{{"theta", &c.theta},
                                        {"amplitudes", &c.amplitudes},
                                        {"sites", &c.sites},
                                        {"periods", &c.periods},
                                        {"steps_per_period", &c.steps_per_period},
                                        {"packet_amplitude", &c.packet_amplitude},
                                        {"packet_width", &c.packet_width}};
  assign_options(options, t, "ring");
  jobs::prepare(model, c, branch);
  const lrchain_lattice_kernels& kernels = lattice_kernels(loaded);
  const jobs::ModelRunLabel label{model_summary_json(loaded), ""};
  ProgressHook progress_hook(progress);  // `progress(fraction)` or None: the run's share done
  c.progress = progress_hook.hook();
  InterruptGuard guard;  // Ctrl-C: the run stops at its next sample, KeyboardInterrupt follows
  const auto report = guard.run([&] { return jobs::simulate_ring(model, kernels, c, label, {}, guard.flag()); });
  const RingRunResult& r = report.result;
  const nlohmann::json& summary = report.summary;
  const py::ssize_t k = py::ssize_t(r.amplitudes.size());
  py::array_t<double> amplitude(k), measured(k), predicted(k), measured_shift(k), predicted_shift(k), disagreement(k);
  for (py::ssize_t i = 0; i < k; ++i) {
    const RingAmplitude& a = r.amplitudes[std::size_t(i)];
    amplitude.mutable_at(i) = a.amplitude;
    const double not_measured = std::numeric_limits<double>::quiet_NaN();  // the plane wave broke up (summary: failure)
    measured.mutable_at(i) = a.broke_up_at ? not_measured : a.measured_frequency;
    predicted.mutable_at(i) = a.predicted_frequency;
    measured_shift.mutable_at(i) = a.broke_up_at ? not_measured : a.measured_shift;
    predicted_shift.mutable_at(i) = a.predicted_shift;
    disagreement.mutable_at(i) = a.relative_disagreement.value_or(std::numeric_limits<double>::quiet_NaN());
  }
  py::dict out;
  out["summary_json"] = summary.dump();
  out["record"] = record_arrays(r.record);
  out["amplitude"] = amplitude;
  out["measured_frequency"] = measured;
  out["predicted_frequency"] = predicted;
  out["measured_shift"] = measured_shift;
  out["predicted_shift"] = predicted_shift;
  out["relative_disagreement"] = disagreement;
  return out;
}

}  // namespace

void register_model_simulate(py::module_& m) {
  m.def("simulate_model_bright", &model_bright, py::arg("model"), py::arg("branch"), py::arg("options"),
        py::arg("progress") = py::none());
  m.def("simulate_ring", &model_ring, py::arg("model"), py::arg("branch"), py::arg("options"),
        py::arg("progress") = py::none());
}

}  // namespace lrchain::python

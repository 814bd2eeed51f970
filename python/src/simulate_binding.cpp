// lrchain.simulate: the simulator's bright, drive and modulated runs (Sec. 4.1-4.3, Sec. 5.1) with
// their records as numpy arrays. The runs are the sim library's run_resonant_chain_bright/run_drive/run_modulated,
// integrated without the GIL; SIGINT stops them at the next step boundary (InterruptGuard).
#include <nlohmann/json.hpp>
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "interrupt_guard.hpp"
#include "progress_hook.hpp"
#include "lrchain/jobs/simulate/bright_outputs.hpp"
#include "lrchain/jobs/simulate/drive_outputs.hpp"
#include "lrchain/jobs/simulate/modulated_outputs.hpp"
#include "lrchain/sim/strain_sites.hpp"
#include "renamed_options.hpp"
#include "run_options.hpp"
#include "run_record_arrays.hpp"

namespace py = pybind11;

namespace lrchain::python {

namespace {
using namespace lrchain::sim;

// The integrator options as run options (stepper, abs_tol, rel_tol, dt).
void add_integrator(std::map<std::string, OptionTarget>& t, IntegratorOptions& o) {
  t.emplace("stepper", &o.stepper);
  t.emplace("abs_tol", &o.abs_tol);
  t.emplace("rel_tol", &o.rel_tol);
  t.emplace("dt", &o.dt);
}

// Runs `run(config, control)` without the GIL, with SIGINT handled and the sampling hook set; returns
// {"summary_json", "record", "fields"} (fields: x_n/y_n or u_n/v_n at every sample, or None);
// `progress(fraction)` (or None) is called as the run advances.
template <class Config, class Run>
py::dict run_python(const Config& config, Run run, bool record_fields, const py::object& observer,
                    const py::object& progress) {
  validate(config);  // before anything is allocated or the handler installed
  SampleRecorder recorder(record_fields, observer);
  ProgressHook progress_hook(progress);
  InterruptGuard guard;
  RunControl control;
  control.stop = guard.flag();
  control.on_sample = recorder.hook();
  control.progress = progress_hook.hook();
  const auto result = guard.run([&] { return run(config, control); });
  py::dict out;
  out["summary_json"] = jobs::to_json(config, result.summary).dump();
  out["record"] = record_arrays(result.record);
  out["fields"] = recorder.arrays();
  return out;
}

py::dict bright(const py::dict& options, bool record_strains, const py::object& observer, const py::object& progress) {
  BrightRunConfig c;
  long sites = long(strain_site_count(c.N));
  std::map<std::string, OptionTarget> t{
      {"params", &c.params}, {"branch", &c.branch}, {"theta", &c.theta}, {"detuning", &c.detuning},
      {"n0", &c.n0}, {"sites", &sites}, {"periods", &c.periods}, {"sample_every", &c.sample_every},
      {"spacetime_every", &c.spacetime_every}, {"snapshot_periods", &c.snapshot_periods},
      {"centre_window", &c.centre_window}, {"error_window_end", &c.error_window_end},
      {"ansatz_ends", &c.ansatz_ends}, {"max_memory", &c.max_memory}};
  add_integrator(t, c.integrator);
  assign_options(options, t, "bright", renamed_options("bright"));
  if (options.contains("dt")) c.integrator.automatic_dt = false;  // a given step is used, as --dt
  c.N = strain_half_width(sites, bright_sites);
  return run_python(c, [](const BrightRunConfig& cfg, const RunControl& rc) { return run_resonant_chain_bright(cfg, rc); },
                    record_strains, observer, progress);
}

py::dict drive(const py::dict& options, bool record_displacements, const py::object& observer, const py::object& progress) {
  DriveRunConfig c;
  std::map<std::string, OptionTarget> t{
      {"params", &c.params}, {"sites", &c.beads}, {"amplitude", &c.amplitude}, {"omega0", &c.omega0},
      {"ramp_rate", &c.ramp_rate}, {"switch_off_time", &c.t_m}, {"t_end", &c.t_end}, {"sample_every", &c.sample_every},
      {"spacetime_every", &c.spacetime_every}, {"snapshot_times", &c.snapshot_times},
      {"front_fraction", &c.front_fraction}, {"front_fit_start", &c.front_fit_start},
      {"front_fit_end", &c.front_fit_end}, {"max_memory", &c.max_memory}};
  add_integrator(t, c.integrator);
  assign_options(options, t, "drive", renamed_options("drive"));
  return run_python(c, [](const DriveRunConfig& cfg, const RunControl& rc) { return run_drive(cfg, rc); },
                    record_displacements, observer, progress);
}

py::dict modulated(const py::dict& options, bool record_displacements, const py::object& observer, const py::object& progress) {
  ModulatedRunConfig c;
  c.checkpoint_every = 0;  // no checkpoint files from Python
  std::map<std::string, OptionTarget> t{
      {"params", &c.params}, {"sites", &c.N}, {"epsilon", &c.epsilon}, {"theta_waves", &c.theta_waves},
      {"modulation_depth", &c.b}, {"t_end", &c.t_end}, {"sample_every", &c.sample_every},
      {"snapshot_times", &c.snapshot_times}, {"contrast_threshold", &c.contrast_threshold},
      {"dark_window", &c.dark_window}, {"speed_fit_start", &c.speed_fit_start},
      {"speed_fit_end", &c.speed_fit_end}, {"max_memory", &c.max_memory}};
  add_integrator(t, c.integrator);
  assign_options(options, t, "modulated", renamed_options("modulated"));
  return run_python(c, [](const ModulatedRunConfig& cfg, const RunControl& rc) { return run_modulated(cfg, rc); },
                    record_displacements, observer, progress);
}

}  // namespace

void register_simulate(py::module_& m) {
  m.def("simulate_bright", &bright, py::arg("options"), py::arg("record_fields"), py::arg("observer"),
        py::arg("progress") = py::none());
  m.def("simulate_drive", &drive, py::arg("options"), py::arg("record_fields"), py::arg("observer"),
        py::arg("progress") = py::none());
  m.def("simulate_modulated", &modulated, py::arg("options"), py::arg("record_fields"), py::arg("observer"),
        py::arg("progress") = py::none());
}

}  // namespace lrchain::python

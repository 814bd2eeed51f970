// lrchain.sweep: `lrchain sweep --config FILE` from Python: the sweep file's job over its points on
// threads in this process (jobs::sweep::run_sweep), results in its HDF5 file (resumed when it exists),
// then the figure the file asks for. Run without the GIL; `progress(fraction)` follows the points
// finished; Ctrl-C stops it after the points running, with their results written, and raises
// KeyboardInterrupt.
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "interrupt_guard.hpp"
#include "lrchain/errors.hpp"
#include "lrchain/jobs/sweep/sweep_config.hpp"
#include "lrchain/jobs/sweep/sweep_figure.hpp"
#include "lrchain/jobs/sweep/sweep_run.hpp"
#include "progress_hook.hpp"

namespace py = pybind11;

namespace lrchain::python {

namespace {

// The sweep of the file `config` (output: "" for the file's own `output`; threads: 0 for all cores);
// returns {"output", "points", "finished", "failed", "ran", "resumed", "seconds", "figures"}.
py::dict sweep(const std::string& config, const std::string& output, int threads, bool retry_failed,
               const py::object& progress) {
  jobs::sweep::SweepConfig c = jobs::sweep::load_sweep_config(config);
  if (!output.empty()) {
    if (const std::string problem = jobs::sweep::output_problem(output, !c.figure.empty()); !problem.empty())
      throw InvalidParameter("output", problem);
    c.output = output;
  }
  const jobs::sweep::Job job = jobs::sweep::make_job(c);
  jobs::sweep::SweepRunOptions o;
  o.threads = threads;
  o.retry_failed = retry_failed;
  o.progress = false;  // no line on stderr: the Python bar instead
  ProgressHook progress_hook(progress);
  const std::function<void(double)> fraction = progress_hook.hook();
  if (fraction)
    o.on_progress = [&fraction](std::size_t done, std::size_t total) {
      fraction(total > 0 ? double(done) / double(total) : 1.0);
    };
  InterruptGuard guard;
  o.stop = guard.flag();
  const jobs::sweep::SweepOutcome r = guard.run([&] {
    jobs::sweep::SweepOutcome outcome = jobs::sweep::run_sweep(c, job, o);
    if (outcome.interrupted) throw Interrupted(SIGINT, "interrupted");  // KeyboardInterrupt; the results are written
    return outcome;
  });
  py::dict out;
  out["output"] = c.output.string();
  out["points"] = r.points;
  out["finished"] = r.finished;
  out["failed"] = r.failed;
  out["ran"] = r.ran;
  out["resumed"] = r.resumed;
  out["seconds"] = r.seconds;
  out["figures"] = jobs::sweep::write_requested_figure(c, job);
  return out;
}

}  // namespace

void register_sweep(py::module_& m) {
  m.def("sweep", &sweep, py::arg("config"), py::arg("output"), py::arg("threads"), py::arg("retry_failed"),
        py::arg("progress") = py::none());
}

}  // namespace lrchain::python

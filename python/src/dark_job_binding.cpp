// lrchain.dark keywords -> DarkConfig, and the dark job run without the GIL (dark_job_binding.hpp).
#include "dark_job_binding.hpp"

#include <csignal>

#include "interrupt_guard.hpp"
#include "progress_hook.hpp"
#include "lrchain/checked_number.hpp"
#include "lrchain/config/option_caps.hpp"
#include "lrchain/errors.hpp"

namespace lrchain::python {

using namespace lrchain::jobs::dark;

Index integer_keyword(double value, const std::string& keyword, std::int64_t least, std::int64_t most) {
  return Index(checked_integer(value, keyword, least, most));
}

DarkConfig dark_config(DarkStep step, double omega_b, const std::optional<std::string>& branch, const std::string& center,
                       std::optional<double> sites, const std::string& mode, double tolerance, double max_iterations) {
  DarkConfig c;
  c.step = step;
  c.omega_b = omega_b;
  c.branch = branch.value_or("");
  c.center = center;
  if (sites) c.sites = integer_keyword(*sites, "sites", config::dark_sites.least, config::dark_sites.most);
  c.mode = mode;
  c.tolerance = tolerance;
  c.max_iterations = integer_keyword(max_iterations, "max_iterations", 1, config::int32_most);
  return c;
}

void set_branch_keywords(DarkConfig& c, double points, double ds, double omega_min, std::optional<double> omega_max,
                         bool floquet, const std::string& parameter, std::optional<double> to) {
  c.parameter = parameter;
  c.to = to;
  c.points = integer_keyword(points, "points", config::dark_points.least, config::dark_points.most);
  c.ds = ds;
  c.omega_min = omega_min;
  c.omega_max = omega_max.value_or(0.0);
  c.branch_floquet = floquet;
}

void set_evolve_keywords(DarkConfig& c, double t_end, double samples, const std::string& perturb, double perturb_size,
                         double seed) {
  c.perturb = perturb;
  c.perturb_size = perturb_size;
  c.seed = std::uint64_t(integer_keyword(seed, "seed", 0, config::int32_most));
  c.t_end = t_end;
  c.samples = integer_keyword(samples, "samples", config::dark_samples.least, config::dark_samples.most);
}

DarkResult run_dark_job(const DarkConfig& c, const pybind11::object& progress) {
  validate(c);
  ProgressHook progress_hook(progress);
  InterruptGuard guard;
  DarkRunHooks hooks;
  hooks.stop = guard.flag();
  hooks.stop_integrations = true;
  hooks.newton_progress = [stop = guard.flag()](const sim::dark::NewtonRecord&) {
    if (stop->load(std::memory_order_relaxed)) throw Interrupted(SIGINT, "interrupted by SIGINT");
  };
  if (const auto report = progress_hook.hook()) {
    hooks.on_point = [report, done = Index(0), points = c.points](const sim::dark::BranchPoint&) mutable {
      report(double(++done) / double(points));
    };
    hooks.evolution_progress = report;
  }
  DarkResult r = guard.run([&] { return run(c, hooks); });
  if (!r.newton.converged) throw NumericalFailure(*failure(r));
  return r;
}

}  // namespace lrchain::python

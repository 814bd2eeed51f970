// JSON pieces shared by the run summaries (run_json.hpp).
#include "run_json.hpp"

#include <string>

namespace lrchain::jobs {

using sim::BlowUp;
using sim::IntegrationStats;
using sim::IntegratorOptions;

nlohmann::json integrator_json(const IntegratorOptions& o) {
  return {{"stepper", std::string(to_string(o.stepper))},
          {"abs_tol", o.abs_tol},
          {"rel_tol", o.rel_tol},
          {"dt", o.dt}};
}

void add_run_status(nlohmann::json& j, double t_end, bool interrupted, bool blew_up,
                    const IntegrationStats& stats, double solve_seconds,
                    const std::optional<BlowUp>& blow_up) {
  j["t_end"] = t_end;
  j["interrupted"] = interrupted;
  j["blew_up"] = blew_up;
  j["failure"] = nullptr;
  if (blow_up)
    j["failure"] = {{"kind", "blow-up"}, {"t", blow_up->t}, {"site", blow_up->site},
                    {"field", blow_up->field}, {"message", blow_up->message()}};
  j["steps"] = stats.steps;
  j["rhs_evaluations"] = stats.rhs_evaluations;
  j["solve_seconds"] = solve_seconds;
}

}  // namespace lrchain::jobs

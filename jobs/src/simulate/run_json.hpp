#pragma once
// JSON pieces shared by the run summaries (bright, drive, modulated): the model object
// (lrchain/model_json.hpp), integrator options, and the run status (time reached, interrupt, blow-up, work, solve time).
// Private to jobs/src.
#include <optional>

#include <nlohmann/json.hpp>

#include "lrchain/model_json.hpp"
#include "lrchain/sim/integrator_options.hpp"

namespace lrchain::jobs {

nlohmann::json integrator_json(const sim::IntegratorOptions& o);
// Sets t_end, interrupted, blew_up, failure (null, or the blow-up: kind, t, site, field, message),
// steps, rhs_evaluations, solve_seconds.
void add_run_status(nlohmann::json& j, double t_end, bool interrupted, bool blew_up,
                    const sim::IntegrationStats& stats, double solve_seconds,
                    const std::optional<sim::BlowUp>& blow_up);

}  // namespace lrchain::jobs

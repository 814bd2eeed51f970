#pragma once
// The sweep jobs that are not simulate experiments, each described by its own small base config
// (docs/sweeps.md) and run in-process:
//   "dark continue":    a dark-breather branch (sim/dark/continuation.hpp) from the eq:xy_app seed,
//                       Newton, then pseudo-arclength continuation in omega_b with Floquet at every
//                       point, as `lrchain dark continue`; scalars: branch points, turning points,
//                       stable/unstable windows and their omega_b extent, max Floquet modulus, ...;
//                       one row per branch point (omega_b, stability, max |lambda|, part, ...).
//   "regime intervals": the focusing theta-intervals of both branches (regime/focusing_intervals.hpp),
//                       as `lrchain regime intervals`; scalars: count, total length, first and last
//                       interval per branch; one row per interval.
#include <string>
#include <string_view>
#include <vector>

#include "lrchain/config/strict_toml.hpp"
#include "lrchain/sim/run_control.hpp"
#include "lrchain/jobs/sweep/job.hpp"

namespace lrchain::jobs::sweep {

// "dark continue" and "regime intervals".
const std::vector<std::string>& study_kinds();
bool is_study_kind(std::string_view kind);
// The base config's schema of a study kind (top level: experiment, [model], [dark] or [regime]).
const config::TableSchema& study_schema(std::string_view kind);
// Checks a base config of a study kind beyond its schema (ConfigError / InvalidParameter).
void check_study_config(std::string_view kind, const config::Document& doc);

std::vector<std::string> study_scalar_names(std::string_view kind);
// The columns of the job's rows, and what their codes mean.
std::vector<std::string> study_row_names(std::string_view kind);
std::string study_rows_legend(std::string_view kind);

// Runs one point from its (overridden) base config; InputError for a config the checks refuse,
// a failed Newton solve or continuation gives status numerical_failure with the reason.
JobResult run_study(std::string_view kind, const config::Document& doc, const sim::RunControl& control);

}  // namespace lrchain::jobs::sweep

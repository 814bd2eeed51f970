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
//   "wave stability":   the exact travelling wave and its Floquet-Bloch growth rates (wave_job.hpp),
//                       as `lrchain wave stability`; scalars: omega and its shift beside the NLS's,
//                       stable, the largest growth rate and its K beside the NLS's, ...; one row per
//                       unstable band; "wave fate" also what the wave becomes on a ring
//                       (`lrchain wave fate`): its fate, breakup time, participation, entropy;
//                       "wave standing" the exact standing wave (`lrchain wave standing`): omega and
//                       its shift, the largest Floquet multiplier modulus on the ring and its growth
//                       rate; one row per multiplier.
//   "bright floquet":   the exact bright breather and its Floquet multipliers (bright_breather_job.hpp),
//                       as `lrchain bright floquet`; scalars: converged, residual, peak, width, stable,
//                       stability class, largest non-trivial |lambda|, ...
//   "bright continue":  its branch, as `lrchain bright continue`; scalars: points, turning points,
//                       stable/unstable points, folds and multiplier crossings; one row per point.
// Each base is of the resonant chain ([model] rho, ...) or of a model file (`model = "models/x.toml"`
// and its [parameters], loaded once per sweep by Job: jobs::ModelSource), as `lrchain dark continue
// --model` and `lrchain regime intervals --model` run it.
#include <string>
#include <string_view>
#include <vector>

#include "lrchain/config/strict_toml.hpp"
#include "lrchain/jobs/model_source.hpp"
#include "lrchain/sim/run_control.hpp"
#include "lrchain/jobs/sweep/job.hpp"

namespace lrchain::jobs::sweep {

// "dark continue", "regime intervals", "wave stability", "wave fate", "wave standing", "bright floquet" and
// "bright continue".
const std::vector<std::string>& study_kinds();
bool is_study_kind(std::string_view kind);
bool is_bright_kind(std::string_view kind);  // "bright floquet" or "bright continue"
bool is_wave_kind(std::string_view kind);    // "wave stability", "wave fate" or "wave standing"
// The base config's schema of a study kind (top level: experiment, [model], [dark], [regime] or [wave]).
const lrchain::config::TableSchema& study_schema(std::string_view kind);
// The schema of a model-file base of a study kind (experiment, model = "FILE", [parameters], and
// [dark] or [regime]).
const lrchain::config::TableSchema& model_study_schema(std::string_view kind);
// Checks a base config of a study kind beyond its schema (ConfigError / InvalidParameter); `model`:
// the loaded model of a model-file base (its [parameters] checked against it), else null.
void check_study_config(std::string_view kind, const lrchain::config::Document& doc, const ModelSource* model = nullptr);

// The scalars of a point; a model-file base's regime scalars are named after the model's branches.
std::vector<std::string> study_scalar_names(std::string_view kind, const ModelDefinition* model = nullptr);
// The columns of the job's rows, and what their codes mean.
std::vector<std::string> study_row_names(std::string_view kind);
std::string study_rows_legend(std::string_view kind, const ModelDefinition* model = nullptr);

// Runs one point from its (overridden) base config (`model`: the loaded model of a model-file base);
// InputError for a config the checks refuse, a failed Newton solve or continuation gives status
// numerical_failure with the reason.
JobResult run_study(std::string_view kind, const lrchain::config::Document& doc, const sim::RunControl& control,
                    const ModelSource* model = nullptr);

}  // namespace lrchain::jobs::sweep

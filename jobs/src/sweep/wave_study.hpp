#pragma once
// The "wave stability", "wave fate" and "wave standing" sweep jobs (docs/sweeps.md): at every point the exact travelling
// wave of `lrchain wave stability` (jobs/wave_job.hpp) and its Floquet-Bloch growth rates, reduced to
// scalars (omega, its shift and the NLS's, the largest growth rate and its K beside the NLS's, stable or
// not) and one row per unstable band; "wave fate" also runs `lrchain wave fate` (the perturbed wave on a
// ring) and adds its fate and diagnostics. Its base: [wave] with the job's options, and the resonant
// chain's [model] or a model file. "wave standing" runs `lrchain wave standing` instead: the exact standing
// wave, its frequency shift and its Floquet multipliers on the ring (one row each). `kind` is "wave
// stability", "wave fate" or "wave standing".
#include <atomic>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "lrchain/config/strict_toml.hpp"
#include "lrchain/jobs/model_source.hpp"
#include "lrchain/jobs/sweep/job.hpp"

namespace lrchain::jobs::sweep {

// [wave]: the options of `lrchain wave stability|fate|standing` (keys as Python names them), from the job's schema.
std::shared_ptr<const lrchain::config::TableSchema> wave_table(std::string_view kind);
std::vector<std::string> wave_scalar_names(std::string_view kind);
const std::vector<std::string>& wave_row_names(std::string_view kind);
std::string wave_rows_legend(std::string_view kind);
// `root`: the base checked against its schema; `source`: a model-file base's model, else null (the
// resonant chain with [model]). The wave job's checks, InvalidParameter naming "[wave] KEY in FILE".
void check_wave_base(std::string_view kind, const lrchain::config::Document& doc,
                     const lrchain::config::CheckedTable& root, const ModelSource* source);
// One point: the wave, its stability (standing: its Floquet multipliers) and the reduction; no wave at an
// amplitude is numerical_failure.
JobResult run_wave(std::string_view kind, const lrchain::config::Document& doc,
                   const lrchain::config::CheckedTable& root, const ModelSource* source,
                   const std::atomic<bool>* stop);

}  // namespace lrchain::jobs::sweep

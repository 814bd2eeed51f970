#pragma once
// The "bright floquet" and "bright continue" sweep jobs (docs/sweeps.md): at every point the exact
// bright breather of `lrchain bright floquet|continue` (jobs/bright_breather_job.hpp), reduced to
// scalars. "bright floquet": one breather (converged, residual, peak, width, its Floquet stability and
// largest non-trivial |lambda|); "bright continue": its branch (points, turning points, stable and
// unstable points, folds and multiplier crossings) and one row per branch point. Its base: [bright]
// with the job's options (omega_b, or edge_offset from the first focusing band edge), and the resonant
// chain's [model] or a model file. `kind` is "bright floquet" or "bright continue".
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "lrchain/config/strict_toml.hpp"
#include "lrchain/jobs/model_source.hpp"
#include "lrchain/jobs/sweep/job.hpp"

namespace lrchain::jobs::sweep {

// [bright]: the options of `lrchain bright floquet|continue` (keys as Python names them) from the
// job's schema, and edge_offset.
std::shared_ptr<const lrchain::config::TableSchema> bright_table(std::string_view kind);
std::vector<std::string> bright_scalar_names(std::string_view kind);
std::vector<std::string> bright_row_names(std::string_view kind);
std::string bright_rows_legend(std::string_view kind);
// `root`: the base checked against its schema; `source`: a model-file base's model, else null (the
// resonant chain with [model]). The bright job's checks, InvalidParameter naming "[bright] KEY in FILE".
void check_bright_base(std::string_view kind, const lrchain::config::Document& doc,
                       const lrchain::config::CheckedTable& root, const ModelSource* source);
// One point: the breather (and its branch) and the reduction. A Newton that fails or a zero that is no
// localized breather is numerical_failure with the job's reason, its scalars kept (converged, residual).
JobResult run_bright(std::string_view kind, const lrchain::config::Document& doc,
                     const lrchain::config::CheckedTable& root, const ModelSource* source);

}  // namespace lrchain::jobs::sweep

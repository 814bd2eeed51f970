#pragma once
// Options' help texts from a job's option schema (lrchain/jobs/option_schema.hpp).
#include <string>
#include <vector>

#include "lrchain/jobs/option_schema.hpp"

namespace lrchain::cli {

// The help of `key` in a job's schema: "doc [range; default D]" or the schema's own help form.
inline std::string schema_help(const std::vector<jobs::JobOption>& options, const std::string& key) {
  return jobs::help_text(jobs::find_option(options, key));
}

// Runs `job` and returns its value; a refusal naming one of the job's Config keys is re-spelled as the
// command's option (t_end -> t-end, snapshot_periods -> snapshots, rho_range -> rho-range: jobs::cli_name).
template <class Job>
auto with_option_names(const std::vector<jobs::JobOption>& options, Job&& job) {
  try {
    return job();
  } catch (const InvalidParameter& e) {
    const std::string name = jobs::cli_name(options, e.parameter());
    if (name == e.parameter()) throw;
    throw jobs::renamed_parameter(e, name);
  }
}

}  // namespace lrchain::cli

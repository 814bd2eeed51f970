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

}  // namespace lrchain::cli

#pragma once
// Running a simulate config's run checks (validate(...) of the run configuration) so that a value
// the file gave is reported at its place: an InvalidParameter naming a key of the config becomes a
// ConfigError "invalid value for 'theta' in [bright] at run.toml:5: <what is allowed>" (exit 2), as
// the schema's own range checks are. Private to jobs/src (experiment_config.cpp,
// more_experiment_config.cpp, model_experiment_config.cpp).
#include <functional>
#include <string>

#include "lrchain/config/strict_toml.hpp"

namespace lrchain::jobs::config {

// Runs `validate`. An InvalidParameter whose parameter (an option spelling such as "ramp-rate" read
// as the key "ramp_rate") is a key written in the file in [experiment_table], [model] or
// [integrator] is rethrown as a ConfigError at that key's line; any other error passes unchanged.
void validate_located(const lrchain::config::CheckedTable& root, const std::string& experiment_table,
                      const std::function<void()>& validate);

// The same for the keys of one table (a model config's [bright], whose top level has no [model]).
void validate_located(const lrchain::config::CheckedTable& table, const std::function<void()>& validate);

}  // namespace lrchain::jobs::config

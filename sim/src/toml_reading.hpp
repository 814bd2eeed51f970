#pragma once
// Shared TOML (toml++) readers of the experiment configs (experiment_config.cpp,
// more_experiment_config.cpp): numbers as TOML numbers or strings in the shared syntax ("1/3",
// "pi/2"), the [model], [integrator] and [output] tables. Private to sim/src.
#include <filesystem>
#include <string>
#include <vector>

#include <toml++/toml.h>

#include "lrchain/params.hpp"
#include "lrchain/sim/integrator.hpp"

namespace lrchain::sim::config {

// Parses a TOML file; std::runtime_error naming the file on a syntax error.
toml::table parse_file(const std::filesystem::path& file);
// Reads t[key] if present (number, or number string); InvalidParameter(key) if malformed.
bool read_number(const toml::table& t, const std::string& key, double& out);
bool read_long(const toml::table& t, const std::string& key, long& out);  // integer-valued
void read_numbers(const toml::table& t, const std::string& key, std::vector<double>& out);
// [model] (rho, kappa, delta0, alpha), [integrator] (stepper, abs_tol, rel_tol, dt), [output] dir.
void read_common(const toml::table& root, Params& p, IntegratorOptions& o, std::string& out_dir);

}  // namespace lrchain::sim::config

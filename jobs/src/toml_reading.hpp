#pragma once
// The parts every simulate config shares (experiment_config.cpp, more_experiment_config.cpp,
// experiment_schema.cpp): the schemas of the [model], [integrator] and [output] tables and of the
// top-level keys, and reading them. Private to jobs/src; the checks are lrchain/config/strict_toml.hpp.
#include <memory>
#include <string>
#include <vector>

#include "lrchain/config/strict_toml.hpp"
#include "lrchain/params.hpp"
#include "lrchain/sim/integrator.hpp"

namespace lrchain::jobs::config {

using namespace lrchain::sim;  // the numerics this job layer runs

using namespace lrchain::config;

// The schema range of a physical parameter (lrchain/params.hpp).
NumberRange range_of(const PhysicalRange& r);
// [model]: rho, kappa, delta0, alpha, with the experiment's defaults.
std::shared_ptr<const TableSchema> model_schema(const Params& defaults);
// [integrator]: stepper (one of `steppers`), abs_tol, rel_tol, dt.
std::shared_ptr<const TableSchema> integrator_schema(const sim::IntegratorOptions& defaults,
                                                     const std::vector<std::string>& steppers);
// [output]: dir.
std::shared_ptr<const TableSchema> output_schema();
// The top level of an experiment of `kind` whose own table is [kind] = `experiment_table`.
TableSchema top_level_schema(const std::string& kind, const Params& model_defaults,
                             const sim::IntegratorOptions& integrator_defaults, const std::vector<std::string>& steppers,
                             std::shared_ptr<const TableSchema> experiment_table);
std::vector<std::string> all_steppers();

// Reads [model], [integrator] and [output] dir of a checked config (keeps defaults for absent keys).
void read_common(const CheckedTable& root, Params& p, sim::IntegratorOptions& o, std::string& out_dir);
// The `name` key, or the file name without its extension.
std::string config_name(const CheckedTable& root);

}  // namespace lrchain::jobs::config

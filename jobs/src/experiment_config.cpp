// Reading a checked "bright" TOML config into its run configuration (experiment_config.hpp).
#include "lrchain/jobs/experiment_config.hpp"

#include "lrchain/jobs/more_experiment_config.hpp"
#include "lrchain/sim/strain_sites.hpp"
#include "located_validation.hpp"
#include "toml_reading.hpp"

namespace lrchain::jobs {

using namespace lrchain::sim;  // the numerics this job layer runs

namespace {

// Reads [bright] into `c`, all but `sites`, which the caller converts (strain_half_width) where its
// refusal is reported at the file's line.
void read_bright(const config::CheckedTable& t, BrightRunConfig& c) {
  std::string branch;
  if (t.read("branch", branch)) c.branch = parse_branch(branch);
  t.read("theta", c.theta);
  double d = 0;
  if (t.read("detuning", d)) c.detuning = d;
  t.read("n0", c.n0);
  t.read("periods", c.periods);
  t.read("sample_every", c.sample_every);
  t.read("spacetime_every", c.spacetime_every);
  t.read("error_window_end", c.error_window_end);
  std::int64_t m = 0;
  if (t.read("centre_window", m)) c.centre_window = Index(m);
  t.read("ansatz_ends", c.ansatz_ends);
  t.read("snapshot_periods", c.snapshot_periods);
  t.read("trailing_fit_start", c.trailing.fit_start);
  t.read("trailing_gap", c.trailing.gap);
  t.read("checkpoint_every", c.checkpoint_every);
}

}  // namespace

ExperimentConfig load_experiment_config(const config::Document& doc) {
  const std::string kind = experiment_kind(doc);
  if (kind != "bright")
    throw config::ConfigError("config file '" + doc.source() + "' is a \"" + kind +
                                  "\" experiment; this reader takes \"bright\" only",
                              doc.source(), 0, "", "experiment");
  const config::CheckedTable root = config::check(doc, experiment_schema(kind));
  ExperimentConfig c;
  c.experiment = kind;
  c.name = config::config_name(root);
  config::read_common(root, c.bright.params, c.bright.integrator, c.out_dir);
  const config::CheckedTable bright = *root.table("bright");  // a required table
  read_bright(bright, c.bright);
  std::int64_t sites = 0;
  const bool has_sites = bright.read("sites", sites);
  config::validate_located(root, "bright", [&] {
    if (has_sites) c.bright.N = strain_half_width(sites, bright_sites);
    validate(c.bright);
  });
  return c;
}

ExperimentConfig load_experiment_config(const std::filesystem::path& file) {
  return load_experiment_config(config::Document::from_file(file));
}

}  // namespace lrchain::jobs

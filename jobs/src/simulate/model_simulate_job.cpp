// The simulate jobs on any model file (model_simulate_job.hpp).
#include "lrchain/jobs/simulate/model_simulate_job.hpp"

#include <optional>

#include "lrchain/coefficients.hpp"
#include "lrchain/jobs/simulate/model_bright_outputs.hpp"
#include "lrchain/jobs/simulate/model_run_hdf5.hpp"
#include "ring_outputs.hpp"
#include "lrchain/jobs/output_files.hpp"
#include "lrchain/jobs/output_lock.hpp"

namespace lrchain::jobs {

namespace {

// The lock on output.dir, the run, the summary with `label` and the files: `write(dir, result,
// summary, figures)` (CSV and figures) or, with output.format hdf5, result.h5 and summary.json.
template <class Config, class Run, class Write>
auto simulate_model_job(const Model& model, const Config& c, const ModelRunLabel& label, const RunOutput& output,
                        Run run, Write write) {
  std::optional<OutputLock> lock;  // (refuses an output directory that is not a directory)
  if (!output.dir.empty()) lock.emplace(output.dir);
  const jobs::OutputListing earlier = output.dir.empty() ? jobs::OutputListing{} : jobs::list_output_files(output.dir);
  auto result = run();
  nlohmann::json j = to_json(model, c, result);
  if (!label.name.empty()) j["name"] = label.name;
  j["model"] = label.model;
  if (!output.dir.empty()) {
    j["out"] = output.dir;
    j["figures"] = output.format == "hdf5" ? write_hdf5_outputs(output.dir, result, j)
                                           : write(output.dir, result, j, output.figures);
    jobs::record_stale_files(output.dir, earlier, j);
  }
  return SimulateReport<decltype(result)>{std::move(result), std::move(j), {}};
}

// The branch by name (none: the model's only one), every option, theta on the branch.
template <class Config>
void prepare_run(const Model& model, Config& c, const std::string& branch) {
  c.branch = model.branch_or_only(branch);
  sim::validate(c);
  coefficients(model, c.branch, c.theta);  // theta on the branch (InvalidParameter otherwise)
}

}  // namespace

void prepare(const Model& model, sim::ModelBrightConfig& c, const std::string& branch) { prepare_run(model, c, branch); }
void prepare(const Model& model, sim::RingRunConfig& c, const std::string& branch) { prepare_run(model, c, branch); }

SimulateReport<sim::ModelBrightResult> simulate_model_bright(const Model& model, const lrchain_lattice_kernels& kernels,
                                                             sim::ModelBrightConfig c, const ModelRunLabel& label,
                                                             const RunOutput& output, const std::atomic<bool>* stop) {
  const sim::ModelBrightAnsatz check(model, kernels, c.branch, c.theta, c.detuning, c.n0);  // focusing, detuning
  c.stop = stop;
  return simulate_model_job(
      model, c, label, output, [&] { return sim::run_bright(model, kernels, c); },
      [](const std::string& d, const auto& r, const auto& j, bool f) { return write_model_bright_outputs(d, r, j, f); });
}

SimulateReport<sim::RingRunResult> simulate_ring(const Model& model, const lrchain_lattice_kernels& kernels,
                                                 sim::RingRunConfig c, const ModelRunLabel& label,
                                                 const RunOutput& output, const std::atomic<bool>* stop) {
  sim::bloch_mode(model, kernels, c.branch, c.theta);
  c.stop = stop;
  return simulate_model_job(
      model, c, label, output, [&] { return sim::run_ring(model, kernels, c); },
      [](const std::string& d, const auto& r, const auto& j, bool f) { return write_ring_outputs(d, r, j, f); });
}

}  // namespace lrchain::jobs

// The simulate jobs of the resonant chain (simulate_job.hpp): validate, lock, run, summary, files.
#include "lrchain/jobs/simulate/simulate_job.hpp"

#include <filesystem>
#include <optional>
#include <system_error>
#include <vector>

#include "lrchain/errors.hpp"
#include "lrchain/jobs/checkpoint/checkpoint_files.hpp"
#include "lrchain/jobs/simulate/bright_outputs.hpp"
#include "lrchain/jobs/simulate/drive_outputs.hpp"
#include "lrchain/jobs/simulate/modulated_outputs.hpp"
#include "lrchain/output_target.hpp"
#include "lrchain/jobs/output_files.hpp"
#include "lrchain/jobs/output_lock.hpp"
#include "lrchain/jobs/result_hdf5.hpp"

namespace lrchain::jobs {

namespace {

namespace fs = std::filesystem;

// Where checkpoints go: the given file, else DIR/checkpoint.bin with an output directory (else none).
std::string checkpoint_path(const std::string& checkpoint, const std::string& dir) {
  if (!checkpoint.empty()) return checkpoint;
  if (!dir.empty()) return (fs::path(dir) / "checkpoint.bin").string();
  return {};
}

// Refuses a checkpoint path that is a directory, a device, FIFO or socket, or in a directory that
// does not exist (other than `dir`), and a `dir` that is not a directory or where the run's files
// would not fit.
template <class Config>
void check_output(const Config& c, const std::string& dir) {
  std::error_code ec;
  if (!c.checkpoint_file.empty()) {
    if (fs::is_directory(c.checkpoint_file, ec))
      throw InvalidParameter("checkpoint", "'" + c.checkpoint_file + "' is a directory; give a file name");
    try {
      check_output_target(c.checkpoint_file);
    } catch (const InputError& e) {
      throw InvalidParameter("checkpoint", e.what());
    }
    // Its directory must exist (nothing is created for it), unless it is the output directory, which the run makes.
    const fs::path file(c.checkpoint_file);
    const fs::path directory = file.has_parent_path() ? file.parent_path() : fs::path(".");
    const bool is_out = !dir.empty() && (directory == fs::path(dir) || fs::weakly_canonical(directory, ec) ==
                                                                           fs::weakly_canonical(fs::path(dir), ec));
    if (!is_out && !fs::is_directory(directory, ec))
      throw InvalidParameter("checkpoint", "the directory '" + directory.string() + "' of '" + c.checkpoint_file +
                                               "' does not exist; create it first (lrchain creates only --out)");
  }
  if (dir.empty()) return;
  if (fs::exists(dir, ec) && !fs::is_directory(dir, ec))
    throw InputError("--out '" + dir + "' exists and is not a directory");
  sim::check_output_space(sim::estimate_resources(c), dir, "out", "choose another --out, or shorten or thin out the run");
}

// Refuses to start a new run (no restart file) whose checkpoint file already exists: it holds an
// earlier run's state, which would be overwritten, or left beside the new outputs as if it belonged to them.
template <class Config>
void refuse_earlier_checkpoint(const Config& c) {
  std::error_code ec;
  if (c.restart_file.empty() && !c.checkpoint_file.empty() && fs::exists(c.checkpoint_file, ec))
    throw InvalidParameter("checkpoint", "'" + c.checkpoint_file +
                                             "' holds the checkpoint of an earlier run: continue it with --restart " +
                                             c.checkpoint_file + ", or move it away, or choose another --out");
}

template <class Config>
void validate_with_output(const Config& c, const std::string& dir) {
  sim::validate(c);
  check_output(c, dir);
}

// Bright and drive runs: checkpoints at the end too when asked for (a file or an interval).
template <class Config>
Config with_checkpoints_at_end(Config c, const std::string& dir) {
  c.checkpoint_at_end = !c.checkpoint_file.empty() || c.checkpoint_every > 0;
  c.checkpoint_file = checkpoint_path(c.checkpoint_file, dir);
  return c;
}

// The job of simulate_job.hpp for one run kind: `run(config, control)` integrates, `write(dir, result,
// summary, figures)` writes the CSV files and figures.
template <class Config, class Run, class Write>
auto simulate_job(const Config& given, const RunOutput& output, const sim::RunControl& control, Run run,
                  Write write) {
  const Config c = with_checkpoints(given, output.dir);
  validate(c, output.dir);  // every option, counts and memory: before anything is created
  std::optional<OutputLock> lock;  // one run per output directory, taken after validation
  if (!output.dir.empty()) lock.emplace(output.dir);
  refuse_earlier_checkpoint(c);  // (after the lock: a run still writing it is named by the lock)
  const jobs::OutputListing earlier = output.dir.empty() ? jobs::OutputListing{} : jobs::list_output_files(output.dir);
  auto result = run(c, with_checkpoint_files(control, c));  // checkpoints as files (checkpoint_files.hpp)
  nlohmann::json j = to_json(c, result.summary);
  j["checkpoint_file"] = c.checkpoint_file.empty() ? nlohmann::json(nullptr) : nlohmann::json(c.checkpoint_file);
  j["checkpoints_written"] = result.summary.checkpoints_written;
  j["t_start"] = result.summary.t_start;
  if (!output.dir.empty()) {
    j["out"] = output.dir;
    j["figures"] = output.format == "hdf5" ? jobs::write_hdf5_outputs(output.dir, result, j)
                                           : write(output.dir, result, j, output.figures);
    // Files of an earlier run this one did not write (never its checkpoint or restart file).
    std::vector<std::string> keep;
    for (const std::string& f : {c.checkpoint_file, c.restart_file})
      if (!f.empty() && fs::path(f).parent_path() == fs::path(output.dir)) keep.push_back(fs::path(f).filename().string());
    jobs::record_stale_files(output.dir, earlier, j, keep);
  }
  return SimulateReport<decltype(result)>{std::move(result), std::move(j), c.checkpoint_file};
}

}  // namespace

sim::BrightRunConfig with_checkpoints(sim::BrightRunConfig c, const std::string& dir) {
  return with_checkpoints_at_end(std::move(c), dir);
}
sim::DriveRunConfig with_checkpoints(sim::DriveRunConfig c, const std::string& dir) {
  return with_checkpoints_at_end(std::move(c), dir);
}
sim::ModulatedRunConfig with_checkpoints(sim::ModulatedRunConfig c, const std::string& dir) {
  c.checkpoint_file = checkpoint_path(c.checkpoint_file, dir);
  return c;
}

void validate(const sim::BrightRunConfig& c, const std::string& dir) { validate_with_output(c, dir); }
void validate(const sim::DriveRunConfig& c, const std::string& dir) { validate_with_output(c, dir); }
void validate(const sim::ModulatedRunConfig& c, const std::string& dir) { validate_with_output(c, dir); }

SimulateReport<sim::BrightRunResult> simulate(const sim::BrightRunConfig& c, const RunOutput& output,
                                              const sim::RunControl& control) {
  return simulate_job(c, output, control, [](const auto& k, const auto& rc) { return sim::run_resonant_chain_bright(k, rc); },
                      [](const std::string& d, const auto& r, const auto& j, bool f) { return write_bright_outputs(d, r, j, f); });
}

SimulateReport<sim::DriveRunResult> simulate(const sim::DriveRunConfig& c, const RunOutput& output,
                                             const sim::RunControl& control) {
  return simulate_job(c, output, control, [](const auto& k, const auto& rc) { return sim::run_drive(k, rc); },
                      [](const std::string& d, const auto& r, const auto& j, bool f) { return write_drive_outputs(d, r, j, f); });
}

SimulateReport<sim::ModulatedRunResult> simulate(const sim::ModulatedRunConfig& c, const RunOutput& output,
                                                 const sim::RunControl& control) {
  return simulate_job(c, output, control, [](const auto& k, const auto& rc) { return sim::run_modulated(k, rc); },
                      [](const std::string& d, const auto& r, const auto& j, bool f) { return write_modulated_outputs(d, r, j, f); });
}

}  // namespace lrchain::jobs

#pragma once
// The simulate jobs of the resonant chain (`lrchain simulate bright|drive|modulated`, `simulate
// --config`): a run config (sim::BrightRunConfig, sim::DriveRunConfig, sim::ModulatedRunConfig: every
// option with its default) -> validate (options, counts, memory, checkpoint path, output directory)
// -> run under one lock on the output directory -> result -> JSON summary and files. Front ends pass
// the stop flag and progress hook (sim::RunControl) and turn the report into JSON and an exit code.
#include <string>

#include <nlohmann/json.hpp>

#include "lrchain/sim/resonant_chain_bright_run.hpp"
#include "lrchain/sim/drive_run.hpp"
#include "lrchain/sim/modulated_run.hpp"
#include "lrchain/sim/run_control.hpp"

namespace lrchain::jobs {

// Where a run's files go and how.
struct RunOutput {
  std::string dir;             // data, figures and summary.json (empty: none, only the summary)
  bool figures = true;         // draw the figures with gnuplot (false: data and summary only)
  std::string format = "csv";  // csv (CSV, float32 space-time files, figures) or hdf5 (result.h5, no figures)
};

// A finished (or interrupted, or blown-up) run: its result, its JSON summary as written to
// summary.json (with "out", "figures" and "stale_files" when there is an output directory), and the
// checkpoint file the run wrote to (empty: none).
template <class Result>
struct SimulateReport {
  Result result;
  nlohmann::json summary;
  std::string checkpoint_file;
};

// The run's checkpoints: to c.checkpoint_file, else to DIR/checkpoint.bin when `dir` is given;
// bright and drive runs also write one at the end when checkpoints were asked for (a file or an interval).
sim::BrightRunConfig with_checkpoints(sim::BrightRunConfig c, const std::string& dir);
sim::DriveRunConfig with_checkpoints(sim::DriveRunConfig c, const std::string& dir);
sim::ModulatedRunConfig with_checkpoints(sim::ModulatedRunConfig c, const std::string& dir);

// Checks a run (after with_checkpoints) before anything is written: every option, the counts and
// memory (sim::validate), the checkpoint path (a file in an existing directory, or in `dir`) and the
// output directory (a directory, with room for the run's files). InvalidParameter / InputError.
void validate(const sim::BrightRunConfig& c, const std::string& dir);
void validate(const sim::DriveRunConfig& c, const std::string& dir);
void validate(const sim::ModulatedRunConfig& c, const std::string& dir);

// The job: with_checkpoints, validate, the lock on output.dir (one run per directory), a new run
// refused where an earlier run's checkpoint lies, the run (`control`: stop flag, progress), the
// summary (jobs::to_json with the checkpoint file, checkpoints written and start time) and the files
// in output.dir. An interrupted or blown-up run returns normally after its outputs are written.
SimulateReport<sim::BrightRunResult> simulate(const sim::BrightRunConfig& c, const RunOutput& output,
                                              const sim::RunControl& control = {});
SimulateReport<sim::DriveRunResult> simulate(const sim::DriveRunConfig& c, const RunOutput& output,
                                             const sim::RunControl& control = {});
SimulateReport<sim::ModulatedRunResult> simulate(const sim::ModulatedRunConfig& c, const RunOutput& output,
                                                 const sim::RunControl& control = {});

}  // namespace lrchain::jobs

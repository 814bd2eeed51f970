#pragma once
// `lrchain simulate ring` (and the model-file runs of `simulate`): subcommands registered on the
// `simulate` command by simulate_command.cpp.
#include <CLI/CLI.hpp>
#include <chrono>
#include <iostream>
#include <nlohmann/json.hpp>
#include <memory>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "lrchain/model.hpp"
#include "lrchain/sim/resonant_chain_bright_run.hpp"
#include "lrchain/sim/ring_run.hpp"
#include "lrchain/errors.hpp"
#include "model_option.hpp"
#include "stop_signals.hpp"

namespace lrchain::cli {

// How a model run reports: --out directory, one-line JSON, figures drawn or not, --format (csv|hdf5).
struct ModelRunOutput {
  std::shared_ptr<std::string> out;
  std::shared_ptr<bool> compact_json, figures;
  std::shared_ptr<std::string> format;
};

// The options that only shape the files a run writes to --out (refused without --out).
inline constexpr std::initializer_list<const char*> output_file_options = {"--no-figures", "--figure-format", "--format"};

// Refuses (exit 2), before anything is done, what the `simulate` subcommand `cmd` would ignore:
// --config given with it, the output_file_options without --out (`out` empty), and the options
// among `unavailable` given to `simulate` before the subcommand, which this run (`what`) lacks.
void refuse_ignored_options(const CLI::App& cmd, const std::string& out, std::initializer_list<const char*> unavailable,
                            const std::string& what);

// Calls run(stop) with SIGINT/SIGTERM handled: the model run polls `stop` and ends at its next step
// boundary or sample; the command then exits 130/143 with one line naming the signal.
template <class Run>
auto run_until_signal(Run&& run) {
  StopSignals signals;
  try {
    return run(StopSignals::flag());
  } catch (const Interrupted& e) {
    const int signal = StopSignals::received() != 0 ? StopSignals::received() : e.signal_number();
    throw Interrupted(signal, std::string(e.what()) + " by " + StopSignals::name(signal));
  }
}

// The model as the summary of a model run names it: model_json with its lattice code.
inline nlohmann::json model_run_json(const Model& model, const LatticeCode& code) {
  nlohmann::json j = model_json(model);
  j["lattice_code"] = lattice_code_json(code);
  return j;
}

// Prints the JSON summary of a finished model run with the wall time since `wall0`, as --json asks.
inline void print_model_run(nlohmann::json j, const ModelRunOutput& output, std::chrono::steady_clock::time_point wall0) {
  j["wall_seconds"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
  std::cout << (*output.compact_json ? j.dump() : j.dump(2)) << std::endl;
}

// Numbers as a help text shows a default list: "0 50.125 200".
inline std::string numbers_text(const std::vector<double>& values) {
  std::string s;
  for (double v : values) s += (s.empty() ? "" : " ") + fmt::format("{:g}", v);
  return s;
}

// Adds `ring` to `simulate`.
void register_simulate_ring(CLI::App& simulate, const ModelRunOutput& output);

// `simulate bright --model FILE`: the run of simulate_model_bright.cpp with the bright options
// (`bright`, given on `cmd` or before it on `simulate`); options the model run lacks are refused (exit 2).
void run_model_bright_command(const ModelSelection& selection, const std::string& branch,
                              const sim::BrightRunConfig& bright, const CLI::App& cmd, const ModelRunOutput& output);

// Checks a ring run of `model` on `branch` (options, theta on the ring, --out) before anything is
// written, then runs it, writes `out` (none when empty) and prints the JSON summary (with `name`
// when not empty).
void run_and_report_ring(const ModelSelection& selection, const Model& model, sim::RingRunConfig run,
                         const std::string& branch, const std::string& out, const ModelRunOutput& output,
                         const std::string& name);

// `simulate --config FILE` where FILE names a model file (`model = "models/x.toml"`, experiment
// bright or ring): runs it and returns true; false (nothing done) for the resonant chain's configs.
bool run_model_config(const std::string& file, const CLI::App& simulate, const ModelRunOutput& output);

}  // namespace lrchain::cli

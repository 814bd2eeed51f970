#pragma once
// Running `lrchain` subcommands from `lrchain reproduce`: the same executable, its stdout (the
// JSON summary) and stderr captured in files of the step's directory.
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "steps.hpp"

namespace lrchain::report {

// The running executable (/proc/self/exe).
std::filesystem::path current_executable();

// Runs `lrchain args...` (argv, no shell) with stdout to dir/<log_stem>.json and stderr to
// dir/<log_stem>.log, each written under a temporary name and renamed when the run ends; returns
// the parsed stdout JSON. Throws std::runtime_error with the last lines of stderr if the
// command fails. Appends the command line (paths relative to ctx.out) to `commands`.
nlohmann::json run_lrchain(const StepContext& ctx, const std::vector<std::string>& args,
                           const std::filesystem::path& dir, const std::string& log_stem,
                           std::vector<std::string>& commands);

// SIGINT and SIGTERM while `reproduce` runs: the handler passes the signal on to every child run
// that is running (they stop and exit), and run_lrchain starts no new one. interrupt_signal() is
// the signal received (0 if none).
void forward_interrupts_to_children();
int interrupt_signal();

// Reads a JSON file (throws std::runtime_error naming it if missing or invalid).
nlohmann::json read_json(const std::filesystem::path& file);

}  // namespace lrchain::report

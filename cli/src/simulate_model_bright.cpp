// `lrchain simulate bright --model FILE ...` and `simulate --config` with `model = "FILE"` (bright or ring): the NLS
// bright breather of any model file on its generated lattice (sim/bright_run.hpp).
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <optional>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "lrchain/errors.hpp"
#include "lrchain/jobs/simulate/model_bright_outputs.hpp"
#include "lrchain/jobs/simulate/model_simulate_job.hpp"
#include "lrchain/jobs/model_experiment_config.hpp"
#include "model_option.hpp"
#include "options.hpp"
#include "simulate_model_commands.hpp"

namespace lrchain::cli {

namespace {

// The model bright job (jobs/simulate/model_simulate_job.hpp): checked before the lattice code is
// loaded, run with SIGINT/SIGTERM handled, its JSON summary printed.
void run_and_report_model_bright(const ModelSelection& selection, const Model& model, sim::ModelBrightConfig c,
                                 const std::string& branch, const std::string& out, const ModelRunOutput& output,
                                 const std::string& name) {
  const auto wall0 = std::chrono::steady_clock::now();
  jobs::prepare(model, c, branch);
  const LatticeCode code = lattice_kernels_for(selection, model);
  const auto report = run_until_signal([&](const std::atomic<bool>* stop) {
    return jobs::simulate_model_bright(model, *code.kernels, c, {model_run_json(model, code), name},
                                       {out, *output.figures, *output.format}, stop);
  });
  print_model_run(report.summary, output, wall0);
  for (const auto& warning : jobs::model_bright_warnings(report.result))
    std::fprintf(stderr, "lrchain: warning: %s\n", warning.c_str());
}

}  // namespace

void refuse_ignored_options(const CLI::App& cmd, const std::string& out, std::initializer_list<const char*> unavailable,
                            const std::string& what) {
  if (given_option(cmd, "--config") != nullptr)
    throw InputError("--config runs the experiment in its file; give it without the subcommand " + cmd.get_name());
  for (const char* name : unavailable)
    if (given_option(cmd, name) != nullptr) throw InputError(std::string(name) + " is not available with " + what);
  refuse_without_out(cmd, out, output_file_options);
}

void run_model_bright_command(const ModelSelection& selection, const std::string& branch,
                              const sim::BrightRunConfig& bright, const CLI::App& cmd,
                              const ModelRunOutput& output) {
  // Options of the resonant chain's run that the model run does not have.
  for (const char* name : {"--snapshots", "--spacetime-every", "--error-window", "--checkpoint-every",
                           "--stepper", "--abs-tol", "--rel-tol"})
    if (cmd.count(name) > 0)
      throw InputError(std::string(name) + " is not available with --model (model bright runs use srkn11b, or rkf78 "
                                           "with --ansatz-ends; see lrchain simulate bright --help)");
  refuse_ignored_options(cmd, *output.out, {"--restart", "--checkpoint", "--max-memory"}, "simulate bright --model");
  const Model model = load_selected_model(selection, cmd, bright.params, true);
  sim::ModelBrightConfig c;
  c.theta = bright.theta;
  c.detuning = bright.detuning;
  c.n0 = bright.n0;
  c.N = bright.N;
  c.periods = bright.periods;
  c.sample_every = bright.sample_every;
  c.ansatz_ends = bright.ansatz_ends;
  if (cmd.count("--dt") > 0) c.dt = bright.integrator.dt;
  run_and_report_model_bright(selection, model, c, branch, *output.out, output, "");
}

bool run_model_config(const std::string& file, const CLI::App& simulate, const ModelRunOutput& output) {
  const config::Document doc = config::Document::from_file(file);
  if (!jobs::is_model_experiment(doc)) return false;
  for (const char* name : {"--restart", "--checkpoint", "--max-memory"})
    if (simulate.count(name) > 0) throw InputError(std::string(name) + " is not available with a model-file config");
  const jobs::ModelExperimentConfig mc = jobs::load_model_experiment_config(doc);
  refuse_without_out(simulate, !output.out->empty() ? *output.out : mc.out_dir, output_file_options);
  ModelSelection selection;
  selection.file = mc.model_file;
  for (const auto& [name, value] : mc.parameters) selection.set.push_back(fmt::format("{}={:.17g}", name, value));
  const Model model = load_selected_model(selection, simulate, Params{}, true);
  const std::string out = !output.out->empty() ? *output.out : mc.out_dir;
  if (mc.experiment == "ring")
    run_and_report_ring(selection, model, mc.ring, mc.branch, out, output, mc.name);
  else
    run_and_report_model_bright(selection, model, mc.bright, mc.branch, out, output, mc.name);
  return true;
}

}  // namespace lrchain::cli

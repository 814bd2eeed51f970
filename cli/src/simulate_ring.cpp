// `lrchain simulate ring --model FILE ...`: plane waves on a periodic ring and a small wave packet,
// measured against the derived h and c (sim/ring_run.hpp).
#include <chrono>
#include <cstdio>

#include <fmt/format.h>

#include "lrchain/config/option_caps.hpp"
#include "lrchain/errors.hpp"
#include "lrchain/jobs/simulate/model_simulate_job.hpp"
#include "lrchain/jobs/simulate/simulate_schema.hpp"
#include "model_option.hpp"
#include "options.hpp"
#include "schema_help.hpp"
#include "simulate_model_commands.hpp"

namespace lrchain::cli {

namespace {

struct RingOptions {
  ModelSelection model;
  std::string branch;
  sim::RingRunConfig run;
};

// `simulate ring` from its options: the amplitudes parsed, then run_and_report_ring.
void run_ring_command(const RingOptions& o, const CLI::App& cmd, const ModelRunOutput& output) {
  refuse_ignored_options(cmd, *output.out, {"--restart", "--checkpoint", "--max-memory"}, "simulate ring");
  const Model model = load_selected_model(o.model, cmd, Params{}, true);
  run_and_report_ring(o.model, model, o.run, o.branch, *output.out, output, "");
}

}  // namespace

void run_and_report_ring(const ModelSelection& selection, const Model& model, sim::RingRunConfig run,
                         const std::string& branch, const std::string& out, const ModelRunOutput& output,
                         const std::string& name) {
  const auto wall0 = std::chrono::steady_clock::now();
  jobs::prepare(model, run, branch);
  const LatticeCode code = lattice_kernels_for(selection, model);
  const auto report = run_until_signal([&](const std::atomic<bool>* stop) {
    return jobs::simulate_ring(model, *code.kernels, run, {model_run_json(model, code), name}, {out, *output.figures, *output.format},
                               stop);
  });
  print_model_run(report.summary, output, wall0);
  for (const auto& warning : report.result.warnings) std::fprintf(stderr, "lrchain: warning: %s\n", warning.c_str());
  if (report.result.failure) throw NumericalFailure(*report.result.failure);
}

void register_simulate_ring(CLI::App& simulate, const ModelRunOutput& output) {
  auto o = std::make_shared<RingOptions>();
  auto* ring = simulate.add_subcommand(
      "ring", "Plane waves of a model on a periodic ring: frequency vs amplitude against omega + h U^2/4, and a "
              "small wave packet's speed against c (the derived coefficients checked by the lattice itself)");
  add_model_file_options(*ring, o->model);
  const auto help = [](const char* key) { return schema_help(jobs::ring_options(), key); };
  ring->add_option("--branch", o->branch, help("branch"))->type_name("NAME");
  add_number(*ring, "--theta", o->run.theta, help("theta"))->required();
  add_number_list(*ring, "--amplitudes", o->run.amplitudes, help("amplitudes"));
  add_integer(*ring, "--sites", o->run.sites, config::ring_sites.least, config::ring_sites.most, help("sites"));
  add_number(*ring, "--periods", o->run.periods, help("periods"));
  add_number(*ring, "--steps-per-period", o->run.steps_per_period, help("steps_per_period"));
  ring->add_option_function<std::string>(
          "--packet-amplitude", [o](const std::string& text) { o->run.packet_amplitude = parse_number(text, "packet-amplitude"); },
          help("packet_amplitude"))
      ->type_name("NUM");
  add_number(*ring, "--packet-width", o->run.packet_width, help("packet_width"));
  ring->callback([o, ring, output] { run_ring_command(*o, *ring, output); });
}

}  // namespace lrchain::cli

// `lrchain simulate ring --model FILE ...`: plane waves on a periodic ring and a small wave packet,
// measured against the derived h and c (sim/ring_run.hpp).
#include <chrono>
#include <filesystem>
#include <iostream>
#include <optional>

#include <nlohmann/json.hpp>

#include "lrchain/config/option_caps.hpp"
#include "lrchain/errors.hpp"
#include "lrchain/sim/output_lock.hpp"
#include "lrchain/sim/ring_run.hpp"
#include "model_option.hpp"
#include "options.hpp"
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
  refuse_ignored_options(cmd, *output.out, {"--restart", "--checkpoint", "--max-memory", "--format"},
                         "simulate ring");
  const Model model = load_selected_model(o.model, cmd, Params{}, true);
  run_and_report_ring(o.model, model, o.run, o.branch, *output.out, output, "");
}

}  // namespace

void run_and_report_ring(const ModelSelection& selection, const Model& model, sim::RingRunConfig run,
                         const std::string& branch, const std::string& out, const ModelRunOutput& output,
                         const std::string& name) {
  const auto wall0 = std::chrono::steady_clock::now();
  run.branch = model.branch(branch);
  sim::validate(run);
  coefficients(model, run.branch, run.theta);  // theta on the branch (InvalidParameter otherwise)
  const LatticeCode code = lattice_kernels_for(selection, model);
  const lrchain_lattice_kernels& kernels = *code.kernels;
  sim::bloch_mode(model, kernels, run.branch, run.theta);
  std::optional<sim::OutputLock> lock;  // (refuses an --out that is not a directory)
  if (!out.empty()) lock.emplace(out);
  const sim::OutputListing earlier = out.empty() ? sim::OutputListing{} : sim::list_output_files(out);
  const sim::RingRunResult r = run_until_signal([&](const std::atomic<bool>* stop) {
    run.stop = stop;
    return sim::run_ring(model, kernels, run);
  });
  print_model_run(sim::to_json(model, run, r), model, code, name, out, output, wall0, earlier, [&](const nlohmann::json& summary) {
    return sim::write_ring_outputs(out, r, summary, *output.figures);
  });
}

void register_simulate_ring(CLI::App& simulate, const ModelRunOutput& output) {
  auto o = std::make_shared<RingOptions>();
  auto* ring = simulate.add_subcommand(
      "ring", "Plane waves of a model on a periodic ring: frequency vs amplitude against omega + h U^2/4, and a "
              "small wave packet's speed against c (the derived coefficients checked by the lattice itself)");
  add_model_file_options(*ring, o->model);
  ring->add_option("--branch", o->branch, "branch name of the model (acoustic, optical, branch0, ...)")->required()->type_name("NAME");
  add_number(*ring, "--theta", o->run.theta, "carrier wavenumber 2 pi k / N in (0, pi], e.g. pi/2")->required();
  add_number_list(*ring, "--amplitudes", o->run.amplitudes, "plane-wave amplitudes U of the first field (default 0.02 0.01)");
  add_integer(*ring, "--sites", o->run.sites, config::ring_sites.least, config::ring_sites.most,
              "ring size N (default: the smallest N >= 8 with theta N / (2 pi) whole)");
  add_number(*ring, "--periods", o->run.periods, "carrier periods per frequency measurement (default 400)");
  add_number(*ring, "--steps-per-period", o->run.steps_per_period, "srkn11b steps per carrier period (default 80)");
  ring->add_option_function<std::string>(
          "--packet-amplitude", [o](const std::string& text) { o->run.packet_amplitude = parse_number(text, "packet-amplitude"); },
          "wave-packet amplitude in (0, 10] (default: a tenth of the smallest --amplitudes)")
      ->type_name("NUM");
  add_number(*ring, "--packet-width", o->run.packet_width, "Gaussian width of the packet in sites (default 24)");
  ring->callback([o, ring, output] { run_ring_command(*o, *ring, output); });
}

}  // namespace lrchain::cli

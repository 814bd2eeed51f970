#pragma once
// The simulate jobs on any model file (`lrchain simulate bright --model FILE`, `simulate ring`,
// `simulate --config` with `model = "FILE"`, lrchain.simulate.bright(model=...) and .ring): the
// NLS bright breather on the model's generated lattice (sim/bright_run.hpp) and plane waves
// and a packet on a periodic ring (sim/ring_run.hpp). prepare (branch, options, theta on the
// branch; before the lattice code is loaded) -> simulate (checks against the lattice code, run,
// summary, files).
#include <atomic>
#include <string>

#include <nlohmann/json.hpp>

#include "lrchain/jobs/simulate/simulate_job.hpp"
#include "lrchain/model.hpp"
#include "lrchain/sim/bright_run.hpp"
#include "lrchain/compiled_model_abi.h"
#include "lrchain/sim/ring_run.hpp"

namespace lrchain::jobs {

// Sets c.branch to `branch` of `model` and checks every option and theta on the branch
// (InvalidParameter), before the lattice code is loaded.
void prepare(const Model& model, sim::ModelBrightConfig& c, const std::string& branch);
void prepare(const Model& model, sim::RingRunConfig& c, const std::string& branch);

// How the summary names the run: the model as the front end identifies it (file, hash, lattice
// code), and the run's name (empty: none).
struct ModelRunLabel {
  nlohmann::json model;
  std::string name;
};

// The job after prepare: the checks against the lattice code (a focusing branch and a detuning
// inside the band for the breather; the Bloch mode for the ring), the lock on output.dir, the run
// (`stop` set: lrchain::Interrupted at the next step boundary or sample), the summary labelled with
// `label`, and the files in output.dir: CSV and figures, or with output.format "hdf5" result.h5 and
// summary.json (jobs/simulate/model_run_hdf5.hpp).
SimulateReport<sim::ModelBrightResult> simulate_model_bright(const Model& model, const lrchain_lattice_kernels& kernels,
                                                             sim::ModelBrightConfig c, const ModelRunLabel& label,
                                                             const RunOutput& output,
                                                             const std::atomic<bool>* stop = nullptr);
SimulateReport<sim::RingRunResult> simulate_ring(const Model& model, const lrchain_lattice_kernels& kernels,
                                                 sim::RingRunConfig c, const ModelRunLabel& label,
                                                 const RunOutput& output, const std::atomic<bool>* stop = nullptr);

}  // namespace lrchain::jobs

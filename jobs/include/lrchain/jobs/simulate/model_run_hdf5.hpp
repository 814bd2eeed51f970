#pragma once
// The HDF5 files of the simulate runs on model files: `lrchain simulate bright --model`, `simulate
// ring`, `simulate --config` with `model = "FILE"` given `--format hdf5` (OUT/result.h5 and
// OUT/summary.json, no CSV, no figures), and Python's ModelBrightResult.to_hdf5 and
// RingResult.to_hdf5 (the same file). The layout is the resonant chain's (sim/result_hdf5.hpp):
// root attributes lrchain_result, lrchain_version, git_commit, model (the summary's model object as
// JSON text: name, file_hash, parameters, lattice_code); the series as float64 datasets at the root;
// group snapshots; the /summary tree. Per result:
//   ModelBrightResult  t, E_0, E_1, ... (one per field), energy, centre; snapshots/0 (the final
//                      profiles: columns n, x_0, x_0_ansatz, ...); no energy_density
//   RingResult         packet_t, packet_centre (the wave packet's centre); per plane-wave amplitude U:
//                      amplitude, measured_frequency, predicted_frequency (omega + h U^2/4),
//                      measured_shift, predicted_shift, relative_disagreement (nan where h vanishes);
//                      snapshots empty
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "lrchain/sim/bright_run.hpp"
#include "lrchain/sim/ring_run.hpp"
#include "lrchain/sim/run_record.hpp"

namespace lrchain::jobs {

// A model bright run's record and summary to `path` (temporary name, then renamed; InputError
// naming `path` if its directory is missing or it is not a regular file).
void write_model_bright_hdf5(const std::filesystem::path& path, const sim::RunRecord& record,
                             const nlohmann::json& summary);

// The per-amplitude table of a ring run: the columns named above, one row per amplitude.
sim::TimeSeries ring_amplitude_table(const sim::RingRunResult& r);

// A ring run's packet record, amplitude table and summary to `path` (as write_model_bright_hdf5).
void write_ring_hdf5(const std::filesystem::path& path, const sim::RunRecord& record, const sim::TimeSeries& amplitudes,
                     const nlohmann::json& summary);

// `--format hdf5`: OUT/result.h5 and OUT/summary.json; returns the figures drawn (none).
std::vector<std::string> write_hdf5_outputs(const std::filesystem::path& dir, const sim::ModelBrightResult& r,
                                            const nlohmann::json& summary);
std::vector<std::string> write_hdf5_outputs(const std::filesystem::path& dir, const sim::RingRunResult& r,
                                            const nlohmann::json& summary);

}  // namespace lrchain::jobs

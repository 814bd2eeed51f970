#pragma once
// The HDF5 files of simulation results: one writer per result, used by `lrchain simulate ...
// --format hdf5` and by Python's `result.to_hdf5(path)`, so both give the same file (h5py reads it).
//
// Layout of a bright / drive / modulated run (written to a temporary name, then renamed):
//   root attributes    lrchain_result ("BrightResult", "DriveResult", "ModulatedResult"),
//                      lrchain_version, git_commit, model (JSON text: {"name", "file_hash",
//                      "parameters": {alpha, delta0, kappa, rho}}, as the summary's "model")
//   /<column>          the sampled series, float64, one per column (bright: t, E_x, E_y, energy,
//                      centre; drive: t, energy, front, participation, u0; modulated: t, energy,
//                      contrast, dark_centre, dark_unwrapped)
//   /energy_density    group: attribute quantity; n (sites, float64), t (float64),
//                      values (times x sites, float32)
//   /snapshots/<k>     group per snapshot k = 0, 1, ...: attributes t, tag; group columns with one
//                      float64 dataset per profile column (n, x, y, ...)
//   /summary           the JSON summary as a tree: objects are groups, numbers and strings
//                      attributes (true/false as 0/1), lists of numbers datasets, lists of strings a
//                      JSON attribute, null left out
//   /<x, y | u, v>     optional groups of fields recorded at every sample (Python's record_strains /
//                      record_displacements): n, t, values (float64)
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "lrchain/sim/resonant_chain_bright_run.hpp"
#include "lrchain/sim/drive_run.hpp"
#include "lrchain/sim/modulated_run.hpp"
#include "lrchain/sim/run_record.hpp"

namespace lrchain::jobs {

class Hdf5TreeFile;

// A lattice field recorded at every sample: values[k * n.size() + i] at time t[k] and site n[i].
struct SampledField {
  std::string name;  // group name ("x", "y", "u", "v")
  std::string quantity;
  std::vector<double> n, t, values;
};

// What a result file calls itself (root attribute lrchain_result: the Python result class) and the
// file names of the record's series columns that differ from the record's own (e.g. X -> centre).
struct RecordLayout {
  std::string result_class;
  std::vector<std::pair<std::string, std::string>> renamed;  // record column -> dataset name
};

// The simulation result kinds ("bright", "drive", "modulated") the writers know.
enum class SimulationKind { bright, drive, modulated };
// SimulationKind of "bright", "drive" or "modulated" (InputError otherwise).
SimulationKind simulation_kind(const std::string& name);

// Writes the record and JSON summary of a run of `kind` to `path` (layout above); `extra` are the
// optional per-sample fields. InputError naming `path` if its directory is missing or it is a directory.
void write_simulation_hdf5(const std::filesystem::path& path, SimulationKind kind, const sim::RunRecord& record,
                           const nlohmann::json& summary, const std::vector<SampledField>& extra = {});

// The layout above in an open file, for a result class of the job layer (a model file's bright run,
// a ring run): root attributes, the record's series, energy density and snapshots, /summary.
void write_simulation_tree(Hdf5TreeFile& file, const RecordLayout& layout, const sim::RunRecord& record,
                           const nlohmann::json& summary);

// The writers of the CLI's results (`--format hdf5`): OUT/result.h5 and OUT/summary.json; no figures.
std::vector<std::string> write_hdf5_outputs(const std::filesystem::path& dir, const sim::BrightRunResult& r,
                                            const nlohmann::json& summary);
std::vector<std::string> write_hdf5_outputs(const std::filesystem::path& dir, const sim::DriveRunResult& r,
                                            const nlohmann::json& summary);
std::vector<std::string> write_hdf5_outputs(const std::filesystem::path& dir, const sim::ModulatedRunResult& r,
                                            const nlohmann::json& summary);

// The columns of `series` as float64 datasets at the root, named as the series names them unless
// `renamed` (series column -> dataset name) says otherwise.
void write_series_datasets(Hdf5TreeFile& file, const sim::TimeSeries& series,
                           const std::vector<std::pair<std::string, std::string>>& renamed = {});

// Writes `j` below the group `group` ("" for the root) with the summary's rules (layout above).
void write_json_tree(Hdf5TreeFile& file, const std::string& group, const nlohmann::json& j);

// The provenance attributes of the root (lrchain_version, git_commit, model) from a JSON summary
// holding "provenance" and "model" (lrchain/model_json.hpp; the attribute is its JSON text).
void write_provenance_attributes(Hdf5TreeFile& file, const nlohmann::json& summary);

}  // namespace lrchain::jobs

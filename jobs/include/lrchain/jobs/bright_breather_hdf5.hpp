#pragma once
// The HDF5 file of an exact bright breather, branch or evolution: `lrchain bright
// solve|floquet|continue|evolve --out DIR --format hdf5` (DIR/result.h5 beside the CSV files) and
// Python's BrightBreather.to_hdf5, BrightBranch.to_hdf5 and BrightEvolution.to_hdf5 (the same file);
// lrchain.load reads it back. Layout:
//   root attributes  lrchain_result ("BrightBreather", "BrightBranch" or "BrightEvolution"), lrchain_version, git_commit,
//                    model (JSON text: name, file_hash, parameters), omega_b, center, variables (JSON list),
//                    summary_json (the job's JSON summary as text: nulls and booleans kept)
//   datasets         n (sites), z and seed (fields x sites: Z(0) and the NLS seed), branch_z (a branch:
//                    points x fields x sites), floquet_multipliers (complex, when computed); an evolution:
//                    per period m = 0..M t (m T_b), deviation (max |[Z, Zdot](t) - [Z(0), 0]|) and energy
//                    (left out when the model's forces have no potential)
//   /summary         the same summary as a tree (objects groups, numbers and strings attributes, null
//                    left out), for reading with h5py
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "lrchain/jobs/bright_breather_job.hpp"
#include "lrchain/sim/run_record.hpp"

namespace lrchain::jobs::bright_breather {

struct BrightBreatherRecord {
  nlohmann::json summary;              // to_json of the job's result (its "model" the file's model)
  std::vector<std::string> variables;  // the lattice's variables (fields)
  Index sites = 0;
  std::vector<double> z, seed;         // fields x sites, field-major
  bool branch = false;                 // a continuation: BrightBranch, with branch_z
  std::vector<double> branch_z;        // points x fields x sites
  bool evolution = false;              // an evolution: BrightEvolution, with its periods
  sim::TimeSeries periods;             // t, deviation and (a potential) energy per period m = 0..M
};

// The record of a converged job's result (summary: to_json(r)).
BrightBreatherRecord bright_breather_record(const BrightBreatherResult& r);

void write_bright_breather_hdf5(const std::filesystem::path& path, const BrightBreatherRecord& record);

}  // namespace lrchain::jobs::bright_breather

#pragma once
// The HDF5 file of an exact bright breather or branch: `lrchain bright solve|floquet|continue --out DIR
// --format hdf5` (DIR/result.h5 beside the CSV files) and Python's BrightBreather.to_hdf5 and
// BrightBranch.to_hdf5 (the same file); lrchain.load reads it back. Layout:
//   root attributes  lrchain_result ("BrightBreather" or "BrightBranch"), lrchain_version, git_commit,
//                    model (JSON text: name, file_hash, parameters), omega_b, center, variables (JSON list),
//                    summary_json (the job's JSON summary as text: nulls and booleans kept)
//   datasets         n (sites), z and seed (fields x sites: Z(0) and the NLS seed), branch_z (a branch:
//                    points x fields x sites), floquet_multipliers (complex, when computed)
//   /summary         the same summary as a tree (objects groups, numbers and strings attributes, null
//                    left out), for reading with h5py
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "lrchain/jobs/bright_breather_job.hpp"

namespace lrchain::jobs::bright_breather {

struct BrightBreatherRecord {
  nlohmann::json summary;              // to_json of the job's result (its "model" the file's model)
  std::vector<std::string> variables;  // the lattice's variables (fields)
  Index sites = 0;
  std::vector<double> z, seed;         // fields x sites, field-major
  bool branch = false;                 // a continuation: BrightBranch, with branch_z
  std::vector<double> branch_z;        // points x fields x sites
};

// The record of a converged job's result (summary: to_json(r)).
BrightBreatherRecord bright_breather_record(const BrightBreatherResult& r);

void write_bright_breather_hdf5(const std::filesystem::path& path, const BrightBreatherRecord& record);

}  // namespace lrchain::jobs::bright_breather

#pragma once
// The HDF5 file of NLS coefficients: `lrchain coeffs ... --out DIR` (DIR/result.h5; with --table one
// file per branch, DIR/result_<branch>.h5) and Python's Coefficients.to_hdf5 (the same file for an
// array of wavenumbers); lrchain.load reads it back. Layout:
//   root attributes  lrchain_result ("Coefficients"), lrchain_version, git_commit, model (JSON text:
//                    name, file_hash, parameters), branch
//   datasets         theta and, with theta's shape (a scalar for one wavenumber), omega, group_velocity,
//                    curvature, gamma, beta, h, lambda, h_tilde, nonresonance1, nonresonance2 (float64;
//                    NaN where singular, lambda NaN without mean flow) and regime_code (int8: 0 focusing,
//                    1 defocusing, 2 degenerate, 3 singular; attribute flag_meanings)
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "lrchain/jobs/coeffs.hpp"

namespace lrchain::jobs {

// The coefficients of one branch on an array of wavenumbers, as the file holds them.
struct CoefficientsRecord {
  nlohmann::json model;                // model_json of the lattice (name, file_hash, parameters)
  std::string branch;
  std::vector<std::size_t> shape;      // theta's shape; empty: one wavenumber
  std::vector<double> theta;
  // omega, group_velocity, curvature, gamma, beta, h, lambda, h_tilde, nonresonance1, nonresonance2
  std::vector<std::pair<std::string, std::vector<double>>> columns;
  std::vector<std::int8_t> regime_code;
};

// The names of CoefficientsRecord::columns, in the file's order.
const std::vector<std::string>& coefficient_column_names();

// The records of a coeffs result: one wavenumber, or one per branch of the table (theta = pi/8 ... pi).
std::vector<CoefficientsRecord> coefficients_records(const CoeffsResult& result);

// Writes `record` to `path` (temporary name, renamed; InputError naming `path` when it may not be written).
void write_coefficients_hdf5(const std::filesystem::path& path, const CoefficientsRecord& record);

// `lrchain coeffs --out DIR`: DIR/result.h5 (one wavenumber) or DIR/result_<branch>.h5 (the table), under
// the directory's lock; returns the file names written.
std::vector<std::string> write(const CoeffsResult& result, const std::filesystem::path& out);

}  // namespace lrchain::jobs

#pragma once
// The results of a sweep, in memory and on disk. The file is HDF5 (readable with h5py):
//   /axes/<parameter>      the values of each axis
//   /scalars/<name>        one dataset per summary scalar, shaped like the grid (list: one entry
//                          per point); NaN where a point did not give the value
//   /status                int8 per point (legend in its attribute `legend`), /wall_seconds,
//   /reason                why a point failed ("" when it did not)
//   /identity (attributes) what a resumed sweep must match: job, base config, layout, axes
//   root attributes        provenance (lrchain version, git commit, date), the sweep and base configs
// Every write goes to a temporary name and is renamed over the results file.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "lrchain/sim/sweep/job.hpp"
#include "lrchain/sim/sweep/sweep_config.hpp"

namespace lrchain::sim::sweep {

struct SweepResults {
  std::vector<std::string> scalar_names;
  std::size_t points = 0;
  std::vector<double> scalars;        // scalar-major: scalars[s * points + point]
  std::vector<std::int8_t> status;    // PointStatus per point
  std::vector<double> wall_seconds;
  std::vector<std::string> reasons;

  SweepResults(std::vector<std::string> names, std::size_t points);
  void set(std::size_t point, const JobResult& r);
  std::size_t finished() const;  // points whose status is not `missing`
  std::size_t failed() const;    // finished but not ok
};

// (name, value) pairs naming the build and the time: lrchain version, git commit (if known), date.
std::vector<std::pair<std::string, std::string>> sweep_provenance();
// What a resumed sweep must match, as (item, text) pairs.
std::vector<std::pair<std::string, std::string>> sweep_identity(const SweepConfig& c, const std::vector<std::string>& scalar_names);

// Writes the whole results file (temporary name + rename). std::runtime_error if it cannot.
void write_results(const std::filesystem::path& file, const SweepConfig& c, const SweepResults& r);
// Reads the results of an earlier run of the same sweep; InputError naming what changed when the
// file belongs to another sweep, or is not a sweep results file.
SweepResults read_results(const std::filesystem::path& file, const SweepConfig& c,
                          const std::vector<std::string>& scalar_names);
// The CSV view: one row per point (axis values, status, scalars, wall time; temporary name + rename).
void write_results_csv(const std::filesystem::path& file, const SweepConfig& c, const SweepResults& r);

}  // namespace lrchain::sim::sweep

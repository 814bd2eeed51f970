#pragma once
// The results of a sweep, in memory and on disk. The file is HDF5 (readable with h5py):
//   /axes/<parameter>      the values of each axis
//   /scalars/<name>        one dataset per summary scalar, shaped like the grid (list: one entry
//                          per point); NaN where a point did not give the value
//   /status                int8 per point (legend in its attribute `legend`), /wall_seconds,
//   /reason                why a point failed ("" when it did not)
//   /rows/point, /rows/<column>  jobs with rows (Job::row_names()): the rows of all points, in
//                          point order, the point each belongs to, the columns' meaning in the
//                          group's attribute `legend`
//   /checksum              per point, the SHA-256 (32 bytes) of its record: index, status, wall
//                          time, scalars, reason, rows; verified when a sweep resumes
//   /identity (attributes) what a resumed sweep must match: job, base config, layout, axes
//   root attributes        provenance (lrchain version, git commit, compiler, build type, date;
//                          lrchain/provenance.hpp), the sweep and base configs
// Every write goes to a temporary name and is renamed over the results file.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "lrchain/sha256.hpp"
#include "lrchain/jobs/sweep/job.hpp"
#include "lrchain/jobs/sweep/sweep_config.hpp"

namespace lrchain::jobs::sweep {

struct SweepResults {
  std::vector<std::string> scalar_names;
  std::size_t points = 0;
  std::vector<double> scalars;        // scalar-major: scalars[s * points + point]
  std::vector<std::int8_t> status;    // PointStatus per point
  std::vector<double> wall_seconds;
  std::vector<std::string> reasons;
  std::vector<std::string> row_names;        // empty: the job has no rows
  std::string rows_legend;
  std::vector<std::vector<double>> rows;     // per point, row-major (row_names.size() per row)

  SweepResults(std::vector<std::string> names, std::size_t points, std::vector<std::string> row_names = {},
               std::string rows_legend = {});
  // Empty results of the job's scalars and rows over the sweep's points.
  SweepResults(const Job& job, std::size_t points);
  void set(std::size_t point, const JobResult& r);
  std::size_t finished() const;  // points whose status is not `missing`
  std::size_t failed() const;    // finished but not ok
  // The SHA-256 of every point's record (/checksum), computed when first needed and again when a
  // point is set.
  const std::vector<Sha256Digest>& checksums() const;

 private:
  mutable std::vector<Sha256Digest> checksums_;  // all-zero: not computed yet
};

// (name, value) pairs of the library's provenance (lrchain/provenance.hpp): lrchain version, git
// commit ("unknown" outside a checkout), compiler, build type, date.
std::vector<std::pair<std::string, std::string>> sweep_provenance();
// What a resumed sweep must match, as (item, text) pairs.
std::vector<std::pair<std::string, std::string>> sweep_identity(const SweepConfig& c, const std::vector<std::string>& scalar_names,
                                                                const std::vector<std::string>& row_names = {});

// Writes the whole results file (temporary name + rename). std::runtime_error if it cannot.
void write_results(const std::filesystem::path& file, const SweepConfig& c, const SweepResults& r);
// Reads the results of an earlier run of the same sweep; InputError naming what changed when the
// file belongs to another sweep, or is not a sweep results file; InputError naming the file and
// the first bad point when a record does not match its checksum or has an unknown status code, or
// when the file is truncated or damaged.
SweepResults read_results(const std::filesystem::path& file, const SweepConfig& c,
                          const std::vector<std::string>& scalar_names);
SweepResults read_results(const std::filesystem::path& file, const SweepConfig& c, const Job& job);
// The CSV view: one row per point (axis values, status, scalars, wall time; temporary name + rename).
void write_results_csv(const std::filesystem::path& file, const SweepConfig& c, const SweepResults& r);
// The rows as CSV (axis values of the point, then the row's columns), for jobs with rows.
void write_rows_csv(const std::filesystem::path& file, const SweepConfig& c, const SweepResults& r);

}  // namespace lrchain::jobs::sweep

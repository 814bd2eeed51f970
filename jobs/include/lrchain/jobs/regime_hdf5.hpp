#pragma once
// The HDF5 files of the regime jobs: focusing intervals (`lrchain regime intervals --out DIR`,
// DIR/result.h5; Python's Intervals.to_hdf5), regime maps (`lrchain regime map --format hdf5`: per
// branch DIR/result.h5, or DIR/result_<branch>.h5 for two or more; Python's RegimeMap.to_hdf5) and
// boundary curves (Python's BoundaryCurve.to_hdf5; a map file holds its panel's curves the same way).
// lrchain.load reads each back. Every file has the root attributes lrchain_result, lrchain_version,
// git_commit, model (JSON text: name, file_hash, parameters) and branch. Lists of names are JSON text.
//   Intervals      datasets lo, hi (intervals), roots; attributes lo_cause, hi_cause, root_cause
//   RegimeMap      attributes plane, x_name, y_name; datasets x, y, values (int8, y x x: -1 outside the
//                  band, 0 defocusing, 1 focusing, 2 singular); group curves/<k> per traced curve
//                  (attribute cause, dataset points (k x 2): parameter, theta or omega)
//   BoundaryCurve  attributes axis, y_name, cause; dataset points (k x 2)
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "lrchain/jobs/regime_job.hpp"

namespace lrchain::jobs {

struct IntervalsRecord {
  nlohmann::json model;
  std::string branch;
  std::vector<double> lo, hi, roots;
  std::vector<std::string> lo_cause, hi_cause, root_cause;
};

// One traced zero curve: its cause and points (x, y) row by row.
struct CurveRecord {
  std::string cause;
  std::vector<double> points;  // k x 2
};

struct RegimeMapRecord {
  nlohmann::json model;
  std::string branch, plane, x_name, y_name;
  std::vector<double> x, y;
  std::vector<std::int8_t> values;  // y.size() x x.size()
  std::vector<CurveRecord> curves;
};

struct BoundaryCurveRecord {
  nlohmann::json model;
  std::string branch, axis, y_name;  // y_name: theta, or omega in the (delta0, omega) plane
  CurveRecord curve;
};

IntervalsRecord intervals_record(const RegimeIntervalsResult& result);
// One record per panel (branch) of a map.
std::vector<RegimeMapRecord> regime_map_records(const RegimeMapResult& result);
CurveRecord curve_record(const regime::BoundaryCurve& curve);

void write_intervals_hdf5(const std::filesystem::path& path, const IntervalsRecord& record);
void write_regime_map_hdf5(const std::filesystem::path& path, const RegimeMapRecord& record);
void write_boundary_curve_hdf5(const std::filesystem::path& path, const BoundaryCurveRecord& record);

// `lrchain regime intervals --out DIR`: DIR/result.h5 under the directory's lock; returns its name.
std::vector<std::string> write_hdf5(const RegimeIntervalsResult& result, const std::filesystem::path& out);
// `lrchain regime map --format hdf5`: the maps' files in `out` (beside the CSV files); returns their names.
std::vector<std::string> write_hdf5(const RegimeMapResult& result, const std::filesystem::path& out);

}  // namespace lrchain::jobs

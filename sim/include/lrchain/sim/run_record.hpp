#pragma once
// What a simulation run records: scalar time series, a space-time field (e.g. the energy density
// e_n(t), eq:edensity) and snapshots of lattice profiles. Plain data, written out by output_files.
#include <cstddef>
#include <string>
#include <vector>

#include "lrchain/index.hpp"

namespace lrchain::sim {

// Columns of numbers sampled in time; data is row-major with names.size() entries per row.
struct TimeSeries {
  std::vector<std::string> names;
  std::vector<double> data;
  std::size_t rows() const { return names.empty() ? 0 : data.size() / names.size(); }
  double at(std::size_t row, std::size_t col) const { return data[row * names.size() + col]; }
};

// A field f(n, t) on sites n = first_label .. first_label + sites - 1, one row per time.
struct SpaceTime {
  std::string quantity;   // e.g. "e_n" or "u_dot"
  Index first_label = 0;  // paper label of the first site
  std::size_t sites = 0;
  std::vector<double> times;
  std::vector<float> values;  // row-major, sites per row
};

// Lattice profiles at one time; data is row-major with names.size() columns (first one "n").
struct Snapshot {
  double t = 0;
  std::string tag;  // file-name tag, e.g. "t0", "t145"
  std::vector<std::string> names;
  std::vector<double> data;
};

struct RunRecord {
  TimeSeries series;
  std::vector<SpaceTime> fields;
  std::vector<Snapshot> snapshots;
};

}  // namespace lrchain::sim

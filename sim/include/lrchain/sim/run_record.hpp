#pragma once
// What a simulation run records: scalar time series, a space-time field (e.g. the energy density
// e_n(t), eq:edensity) and snapshots of lattice profiles. Plain data, written out by output_files.
#include <string>
#include <vector>

#include "lrchain/index.hpp"

namespace lrchain::sim {

// Columns of numbers sampled in time; data is row-major with names.size() entries per row.
struct TimeSeries {
  std::vector<std::string> names;
  std::vector<double> data;
  Index rows() const { return names.empty() ? 0 : static_cast<Index>(data.size() / names.size()); }
  double at(Index row, Index col) const { return data[static_cast<std::size_t>(row * static_cast<Index>(names.size()) + col)]; }
};

// A field f(n, t) on sites n = first_label .. first_label + sites - 1, one row per time.
struct SpaceTime {
  std::string quantity;   // e.g. "e_n" or "u_dot"
  Index first_label = 0;  // paper label of the first site
  Index sites = 0;
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

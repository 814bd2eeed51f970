#pragma once
// A run's RunRecord as numpy arrays, and the sampling hook a Python run adds (x_n(t), y_n(t) on
// request, a Python observer called at every sample).
#include <vector>

#include <pybind11/pybind11.h>

#include "lrchain/sim/run_control.hpp"
#include "lrchain/sim/run_record.hpp"

namespace lrchain::python {

// {"series": {column: array}, "fields": [{quantity, first_label, n, t, values (rows, sites)}],
//  "snapshots": [{t, tag, columns: {name: array}}]}.
pybind11::dict record_arrays(const sim::RunRecord& record);

// Records the lattice fields at every sample (if asked) and calls a Python observer(t, primary,
// secondary, energy_density) with the GIL taken (if given, i.e. not None).
class SampleRecorder {
 public:
  SampleRecorder(bool record_fields, pybind11::object observer);
  // The hook for RunControl::on_sample (empty if there is nothing to do).
  std::function<void(const sim::SampleView&)> hook();
  // {"t", "n", "primary" (rows, sites), "secondary" (rows, sites)} or None if not recorded.
  pybind11::object arrays() const;

 private:
  bool record_;
  pybind11::object observer_;
  std::vector<double> t_, primary_, secondary_;
  std::size_t sites_ = 0;
  long first_label_ = 0;
};

}  // namespace lrchain::python

// RunRecord -> numpy arrays, and the per-sample hook of Python runs (run_record_arrays.hpp).
#include "run_record_arrays.hpp"

#include <algorithm>
#include <pybind11/numpy.h>

namespace py = pybind11;

namespace lrchain::python {

namespace {
template <class T>
py::array_t<T> copy_array(const T* data, std::vector<py::ssize_t> shape) {
  py::array_t<T> a(shape);
  std::copy(data, data + a.size(), a.mutable_data());
  return a;
}

py::array_t<double> labels(long first, std::size_t count) {
  py::array_t<double> n(static_cast<py::ssize_t>(count));
  for (std::size_t i = 0; i < count; ++i) n.mutable_at(i) = double(first + long(i));
  return n;
}
}  // namespace

py::dict record_arrays(const sim::RunRecord& record) {
  py::dict series;
  const Index rows = record.series.rows(), cols = static_cast<Index>(record.series.names.size());
  for (Index c = 0; c < cols; ++c) {
    py::array_t<double> column(rows);
    for (Index r = 0; r < rows; ++r) column.mutable_at(r) = record.series.at(r, c);
    series[py::str(record.series.names[static_cast<std::size_t>(c)])] = column;
  }
  py::list fields;
  for (const sim::SpaceTime& f : record.fields) {
    py::dict d;
    d["quantity"] = f.quantity;
    d["n"] = labels(f.first_label, f.sites);
    d["t"] = copy_array(f.times.data(), {py::ssize_t(f.times.size())});
    d["values"] = copy_array(f.values.data(), {py::ssize_t(f.times.size()), py::ssize_t(f.sites)});
    fields.append(d);
  }
  py::list snapshots;
  for (const sim::Snapshot& s : record.snapshots) {
    py::dict columns;
    const std::size_t k = s.names.size(), n = k ? s.data.size() / k : 0;
    for (std::size_t c = 0; c < k; ++c) {
      py::array_t<double> column(static_cast<py::ssize_t>(n));
      for (std::size_t r = 0; r < n; ++r) column.mutable_at(r) = s.data[r * k + c];
      columns[py::str(s.names[c])] = column;
    }
    py::dict d;
    d["t"] = s.t;
    d["tag"] = s.tag;
    d["columns"] = columns;
    snapshots.append(d);
  }
  py::dict out;
  out["series"] = series;
  out["fields"] = fields;
  out["snapshots"] = snapshots;
  return out;
}

SampleRecorder::SampleRecorder(bool record_fields, py::object observer)
    : record_(record_fields), observer_(std::move(observer)) {}

std::function<void(const sim::SampleView&)> SampleRecorder::hook() {
  if (!record_ && observer_.is_none()) return {};
  return [this](const sim::SampleView& v) {
    if (record_) {
      sites_ = v.primary.size();
      first_label_ = v.first_label;
      t_.push_back(v.t);
      primary_.insert(primary_.end(), v.primary.begin(), v.primary.end());
      secondary_.insert(secondary_.end(), v.secondary.begin(), v.secondary.end());
    }
    if (!observer_.is_none()) {
      py::gil_scoped_acquire gil;
      observer_(v.t, copy_array(v.primary.data(), {py::ssize_t(v.primary.size())}),
                copy_array(v.secondary.data(), {py::ssize_t(v.secondary.size())}),
                copy_array(v.energy_density.data(), {py::ssize_t(v.energy_density.size())}));
    }
  };
}

py::object SampleRecorder::arrays() const {
  if (!record_) return py::none();
  py::dict d;
  d["t"] = copy_array(t_.data(), {py::ssize_t(t_.size())});
  d["n"] = labels(first_label_, sites_);
  d["primary"] = copy_array(primary_.data(), {py::ssize_t(t_.size()), py::ssize_t(sites_)});
  d["secondary"] = copy_array(secondary_.data(), {py::ssize_t(t_.size()), py::ssize_t(sites_)});
  return d;
}

}  // namespace lrchain::python

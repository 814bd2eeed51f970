#pragma once
// What the _hdf5 module's writers share: a numpy array as a vector, and the writers of
// regime_bright_writers.cpp.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <vector>

namespace lrchain::python {

// The elements of an array-like `a` in C order, converted to T (TypeError for a non-numeric one).
template <class T>
std::vector<T> vector_of(const pybind11::handle& a) {
  const auto c = pybind11::array_t<T, pybind11::array::c_style | pybind11::array::forcecast>::ensure(a);
  if (!c) throw pybind11::type_error("to_hdf5: expected a numeric array");
  return std::vector<T>(c.data(), c.data() + c.size());
}

// write_coefficients, write_intervals, write_regime_map, write_boundary_curve, write_bright_breather.
void register_regime_and_bright_writers(pybind11::module_& m);

}  // namespace lrchain::python

// Output arrays of the batch coefficient evaluation and the wavenumber checks (coefficient_arrays.hpp).
#include "coefficient_arrays.hpp"

#include <cmath>
#include <fmt/format.h>
#include <numbers>

#include "lrchain/errors.hpp"

namespace py = pybind11;

namespace lrchain::python {

CoefficientArrays::CoefficientArrays(const std::vector<py::ssize_t>& shape) : regime_array_(shape) {
  arrays_.reserve(kCoefficientFieldCount);
  for (int k = 0; k < kCoefficientFieldCount; ++k) {
    arrays_.emplace_back(shape);
    columns.field[k] = arrays_.back().mutable_data();
  }
  columns.regime = regime_array_.mutable_data();
}

py::dict CoefficientArrays::to_dict() const {
  py::dict result;
  for (int k = 0; k < kCoefficientFieldCount; ++k) result[kCoefficientFields[k]] = arrays_[k];
  result["regime"] = regime_array_;
  return result;
}

std::vector<py::ssize_t> shape_of(const Thetas& theta) {
  return std::vector<py::ssize_t>(theta.shape(), theta.shape() + theta.ndim());
}

std::string wavenumber_position(const Thetas& theta, py::ssize_t i) {
  return theta.ndim() == 0 ? std::string() : fmt::format(" (theta[{}] = {})", i, theta.data()[i]);
}

void validate_wavenumbers(const Thetas& theta) {
  const double* t = theta.data();
  for (py::ssize_t i = 0; i < theta.size(); ++i)
    if (!(std::isfinite(t[i]) && t[i] > -std::numbers::pi && t[i] <= std::numbers::pi))
      throw InvalidParameter("theta", "must be a wavenumber in (-pi, pi]" + wavenumber_position(theta, i));
}

}  // namespace lrchain::python

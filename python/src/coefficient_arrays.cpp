// Output arrays of the batch coefficient evaluation and the wavenumber checks (coefficient_arrays.hpp).
#include "coefficient_arrays.hpp"

#include <cmath>
#include <fmt/format.h>
#include <numbers>

#include "lrchain/errors.hpp"

namespace py = pybind11;

namespace lrchain::python {

namespace {
// The array out[name] if it can take the result in place: InvalidParameter("out") otherwise.
template <class T>
py::array_t<T> reusable(const py::dict& out, const char* name, const std::vector<py::ssize_t>& shape) {
  if (!out.contains(name)) throw InvalidParameter("out", fmt::format("has no array '{}'", name));
  const py::object a = out[name];
  if (!py::isinstance<py::array_t<T>>(a))
    throw InvalidParameter("out", fmt::format("'{}' is not an array of the result's dtype", name));
  auto array = py::reinterpret_borrow<py::array_t<T>>(a);
  if (!(array.flags() & py::array::c_style) || !array.writeable() ||
      std::vector<py::ssize_t>(array.shape(), array.shape() + array.ndim()) != shape)
    throw InvalidParameter("out", fmt::format("'{}' must be a writable C-contiguous array of theta's shape", name));
  return array;
}
}  // namespace

CoefficientArrays::CoefficientArrays(const std::vector<py::ssize_t>& shape, const py::object& out) {
  arrays_.reserve(kCoefficientFieldCount);
  if (out.is_none()) {
    for (int k = 0; k < kCoefficientFieldCount; ++k) arrays_.emplace_back(shape);
    regime_array_ = py::array_t<std::int8_t>(shape);
  } else {
    if (!py::isinstance<py::dict>(out)) throw InvalidParameter("out", "must be an earlier result of theta's shape");
    const auto d = out.cast<py::dict>();
    for (int k = 0; k < kCoefficientFieldCount; ++k) arrays_.push_back(reusable<double>(d, kCoefficientFields[k], shape));
    regime_array_ = reusable<std::int8_t>(d, "regime", shape);
  }
  for (int k = 0; k < kCoefficientFieldCount; ++k) columns.field[k] = arrays_[k].mutable_data();
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

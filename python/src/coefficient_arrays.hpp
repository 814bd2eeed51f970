#pragma once
// The result of a batch coefficient evaluation: one numpy array per NLS coefficient with the shape
// of theta and the regime codes (int8), shared by the resonant chain's and the loaded models' loops.
#include <cstdint>
#include <string>
#include <vector>

#include <pybind11/numpy.h>

#include "lrchain/coefficients.hpp"
#include "lrchain/coefficients_batch.hpp"
#include "lrchain/params.hpp"

namespace lrchain::python {

using Thetas = pybind11::array_t<double, pybind11::array::c_style | pybind11::array::forcecast>;

// Field names of the result, in the order of CoefficientColumns::field (lrchain/coefficients_batch.hpp).
inline constexpr const auto& kCoefficientFields = kCoefficientColumnNames;
inline constexpr int kCoefficientFieldCount = kCoefficientColumnCount;

class CoefficientArrays {
 public:
  // New arrays of `shape`, or those of `out` ({name: array} of an earlier result, None for new ones)
  // after checking that each is a writable C-contiguous array of `shape` and the right dtype
  // (InvalidParameter("out") otherwise). With the GIL.
  CoefficientArrays(const std::vector<pybind11::ssize_t>& shape, const pybind11::object& out);
  // Writable data of each field (kCoefficientFields order) and of the regime codes.
  CoefficientColumns columns;
  // Stores c at flat index i (no GIL needed).
  void store(pybind11::ssize_t i, const NlsCoefficients& c) { columns.store(i, c); }
  // {name: array, ..., "regime": int8 codes}.
  pybind11::dict to_dict() const;

 private:
  std::vector<pybind11::array_t<double>> arrays_;
  pybind11::array_t<std::int8_t> regime_array_;
};

// The shape of theta as a vector.
std::vector<pybind11::ssize_t> shape_of(const Thetas& theta);

// Throws InvalidParameter("theta") at the first value outside (-pi, pi], naming its index (and
// value) when theta is an array.
void validate_wavenumbers(const Thetas& theta);

// " (theta[i] = value)" for an array, "" for a scalar: the suffix of messages about one wavenumber.
std::string wavenumber_position(const Thetas& theta, pybind11::ssize_t i);

// The resonant chain's coefficients at every wavenumber of theta (coefficients_binding.cpp).
pybind11::dict resonant_chain_coefficient_arrays(const Params& p, const std::string& branch, const Thetas& theta,
                                                 const pybind11::object& out);

}  // namespace lrchain::python

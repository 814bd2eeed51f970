// Dark-breather results as Python objects (dark_arrays.hpp).
#include "dark_arrays.hpp"

#include <algorithm>
#include <complex>
#include <pybind11/complex.h>

namespace py = pybind11;

namespace lrchain::python {

using namespace lrchain::sim::dark;

py::array_t<double> residuals(const NewtonResult& r) {
  py::array_t<double> a(static_cast<py::ssize_t>(r.history.size()));
  for (std::size_t k = 0; k < r.history.size(); ++k) a.mutable_at(k) = r.history[k].residual;
  return a;
}

py::dict measures(const DarkMeasures& m) {
  py::dict d;
  d["norm_squared"] = m.norm_squared;
  d["K_x"] = m.K_x;
  d["K_y"] = m.K_y;
  d["C_x"] = m.C_x;
  d["C_y"] = m.C_y;
  d["E_b"] = m.E_b;
  d["max_strain"] = m.max_strain;
  return d;
}

py::dict floquet_dict(const FloquetResult& f) {
  py::array_t<std::complex<double>> mult(static_cast<py::ssize_t>(f.multipliers.size()));
  std::copy(f.multipliers.begin(), f.multipliers.end(), mult.mutable_data());
  py::dict d;
  d["multipliers"] = mult;
  d["kind"] = f.kind();
  d["max_modulus"] = f.max_modulus;
  d["max_real"] = f.max_real;
  d["max_period_doubling"] = f.max_period_doubling;
  d["max_oscillatory"] = f.max_oscillatory;
  d["near_one"] = f.near_one;
  d["pairing_defect"] = f.pairing_defect;
  d["conjugation_defect"] = f.conjugation_defect;
  d["log_det"] = f.log_det;
  return d;
}

}  // namespace lrchain::python

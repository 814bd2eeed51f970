// Dark-breather results as Python objects (dark_arrays.hpp).
#include "dark_arrays.hpp"

#include <algorithm>
#include <complex>
#include <pybind11/complex.h>
#include <pybind11/stl.h>

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

py::dict evolution_series(const DarkEvolution& e) {
  const auto M = static_cast<py::ssize_t>(e.periods.size());
  py::array_t<double> t(M), E_b(M), C_x(M), K_x(M), position(M), depth(M);
  for (py::ssize_t m = 0; m < M; ++m) {
    const DarkEvolutionPeriod& r = e.periods[static_cast<std::size_t>(m)];
    t.mutable_at(m) = r.t;
    E_b.mutable_at(m) = r.E_b;
    C_x.mutable_at(m) = r.C_x;
    K_x.mutable_at(m) = r.K_x;
    position.mutable_at(m) = r.position;
    depth.mutable_at(m) = r.depth;
  }
  py::dict d;
  d["period"] = e.period;
  d["t"] = t;
  d["E_b"] = E_b;
  d["C_x"] = C_x;
  d["K_x"] = K_x;
  d["position"] = position;
  d["depth"] = depth;
  d["max_strain"] = e.max_strain;
  return d;
}

py::dict branch_arrays(const BranchResult& branch, bool floquet,
                       const std::function<py::dict(const DarkMeasures&)>& measures_of) {
  const auto k = static_cast<py::ssize_t>(branch.points.size());
  py::array_t<double> omega(k), tangent(k), residual(k);
  py::array_t<int> iterations(k);
  py::list measure_rows, floquet_rows;
  for (py::ssize_t i = 0; i < k; ++i) {
    const BranchPoint& b = branch.points[static_cast<std::size_t>(i)];
    omega.mutable_at(i) = b.omega_b;
    tangent.mutable_at(i) = b.tangent_omega;
    residual.mutable_at(i) = b.residual;
    iterations.mutable_at(i) = static_cast<int>(b.iterations);  // int32, as in the HDF5 file
    measure_rows.append(measures_of(b.measures));
    floquet_rows.append(floquet ? py::object(floquet_dict(b.floquet)) : py::object(py::none()));
  }
  py::dict d;
  d["omega_b"] = omega;
  d["tangent_omega"] = tangent;
  d["residual"] = residual;
  d["iterations"] = iterations;
  d["measures"] = measure_rows;
  d["floquet"] = floquet_rows;
  d["turning_points"] = branch.turning_points;
  d["stop_reason"] = branch.stop_reason;
  return d;
}

}  // namespace lrchain::python

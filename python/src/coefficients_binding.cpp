// Batch evaluation of the NLS coefficients (eq:c, eq:ppOmega, eq:gamma, eq:h, eq:lambda, eq:h_tilde)
// over a numpy array of wavenumbers: one validation pass, then one contiguous C++ loop without
// the GIL, writing one output array per coefficient.
#include <cmath>
#include <cstdint>
#include <fmt/format.h>
#include <numbers>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "lrchain/coefficients.hpp"
#include "lrchain/errors.hpp"

namespace py = pybind11;

namespace lrchain::python {

namespace {

using Thetas = py::array_t<double, py::array::c_style | py::array::forcecast>;

// The field names of the result, in the order of the arrays written below.
constexpr const char* kFields[] = {"omega", "group_velocity", "curvature", "gamma",         "beta",
                                   "h",     "lambda",         "h_tilde",   "nonresonance1", "nonresonance2"};
constexpr int kFieldCount = 10;

// Throws InvalidParameter("theta") at the first wavenumber outside (-pi, pi] (or 0 on the
// acoustic branch), naming its index when theta is an array.
void validate_thetas(const double* theta, py::ssize_t n, bool scalar, Branch b) {
  const auto where = [&](py::ssize_t i) { return scalar ? std::string() : fmt::format(" (theta[{}] = {})", i, theta[i]); };
  for (py::ssize_t i = 0; i < n; ++i) {
    const double t = theta[i];
    if (!(std::isfinite(t) && t > -std::numbers::pi && t <= std::numbers::pi))
      throw InvalidParameter("theta", "must be a wavenumber in (-pi, pi]" + where(i));
    if (b == Branch::acoustic && t == 0.0)
      throw InvalidParameter("theta", "must be nonzero on the acoustic branch (theta = 0 is the zero-frequency "
                                      "mode); valid range (-pi, 0) U (0, pi]" + where(i));
  }
}

// Fills the outputs from coefficients_unchecked, element by element (allocation-free).
void evaluate(const Params& p, Branch b, const double* theta, py::ssize_t n, double* const* out,
              std::int8_t* regime) {
  const TaylorCoefficients K = taylor_coefficients(p);
  for (py::ssize_t i = 0; i < n; ++i) {
    const NlsCoefficients c = coefficients_unchecked(p, K, b, theta[i]);
    out[0][i] = c.omega;
    out[1][i] = c.group_velocity;
    out[2][i] = c.curvature;
    out[3][i] = c.gamma;
    out[4][i] = c.beta;
    out[5][i] = c.h;
    out[6][i] = c.lambda;
    out[7][i] = c.h_tilde;
    out[8][i] = c.nonresonance1;
    out[9][i] = c.nonresonance2;
    regime[i] = static_cast<std::int8_t>(c.regime);
  }
}

// {name: array} with the shape of theta; "regime" holds the Regime codes (int8).
py::dict coefficients_array(const Params& p, const std::string& branch, const Thetas& theta) {
  validate(p);
  const Branch b = parse_branch(branch);
  const py::ssize_t n = theta.size();
  const std::vector<py::ssize_t> shape(theta.shape(), theta.shape() + theta.ndim());
  validate_thetas(theta.data(), n, theta.ndim() == 0, b);
  std::vector<py::array_t<double>> arrays;
  double* out[kFieldCount];
  for (int k = 0; k < kFieldCount; ++k) {
    arrays.emplace_back(shape);
    out[k] = arrays.back().mutable_data();
  }
  py::array_t<std::int8_t> regime(shape);
  std::int8_t* codes = regime.mutable_data();
  {
    py::gil_scoped_release release;
    evaluate(p, b, theta.data(), n, out, codes);
  }
  py::dict result;
  for (int k = 0; k < kFieldCount; ++k) result[kFields[k]] = arrays[k];
  result["regime"] = regime;
  return result;
}

}  // namespace

void register_coefficients(py::module_& m) {
  m.def("coefficients_array", &coefficients_array, py::arg("params"), py::arg("branch"), py::arg("theta"),
        "NLS coefficients of one branch at every wavenumber of theta: {name: array}; regime as int8 codes "
        "(regime_names).");
  py::list names;
  for (Regime r : {Regime::focusing, Regime::defocusing, Regime::degenerate, Regime::singular})
    names.append(std::string(to_string(r)));
  m.attr("regime_names") = py::tuple(names);
}

}  // namespace lrchain::python

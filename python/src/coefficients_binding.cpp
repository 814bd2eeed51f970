// lrchain.coefficients of the resonant chain over a numpy array of wavenumbers: the checks with the
// array position in their messages, then lib's vectorised loop (lrchain/coefficients_batch.hpp)
// without the GIL into one output array per coefficient; and the coefficients job at one wavenumber.
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "coefficient_arrays.hpp"
#include "lrchain/errors.hpp"
#include "lrchain/jobs/coeffs.hpp"

namespace py = pybind11;

namespace lrchain::python {

// {name: array} with the shape of theta; "regime" holds the Regime codes (int8).
py::dict resonant_chain_coefficient_arrays(const Params& p, const std::string& branch, const Thetas& theta,
                                           const py::object& out_arrays) {
  validate(p);
  const Branch b = parse_branch(branch);
  validate_wavenumbers(theta);
  if (b == Branch::acoustic)
    for (py::ssize_t i = 0; i < theta.size(); ++i)
      if (theta.data()[i] == 0.0)
        throw InvalidParameter("theta", "must be nonzero on the acoustic branch (theta = 0 is the zero-frequency "
                                        "mode); valid range (-pi, 0) U (0, pi]" + wavenumber_position(theta, i));
  CoefficientArrays out(shape_of(theta), out_arrays);
  {
    py::gil_scoped_release release;
    resonant_chain_coefficients_batch(p, b, {theta.data(), static_cast<std::size_t>(theta.size())}, out.columns);
  }
  return out.to_dict();
}

void register_coefficients(py::module_& m) {
  m.def("coefficients_array", &resonant_chain_coefficient_arrays, py::arg("params"), py::arg("branch"),
        py::arg("theta"), py::arg("out") = py::none(),
        "NLS coefficients of one branch at every wavenumber of theta: {name: array}; regime as int8 codes "
        "(regime_names).");
  m.def(
      "coefficients_scalar",
      [](const Params& p, const std::string& branch, double theta) {
        jobs::CoeffsConfig config;
        config.params = p;
        config.branch = branch;
        config.theta = theta;
        const NlsCoefficients c = jobs::run_coeffs(config).coefficients;
        return py::make_tuple(c.omega, c.group_velocity, c.curvature, c.gamma, c.beta, c.h, c.lambda, c.h_tilde,
                              c.nonresonance1, c.nonresonance2, static_cast<int>(c.regime));
      },
      py::arg("params"), py::arg("branch"), py::arg("theta"),
      "The coefficients job at one wavenumber (fields in coefficients_array order, regime code last): the "
      "reference the batch loop is tested against.");
  py::list names;
  for (Regime r : {Regime::focusing, Regime::defocusing, Regime::degenerate, Regime::singular})
    names.append(std::string(to_string(r)));
  m.attr("regime_names") = py::tuple(names);
}

}  // namespace lrchain::python

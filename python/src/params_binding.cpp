// lrchain.Params: the resonant chain's parameters (Sec. 2), validated on construction.
#include <fmt/format.h>
#include <pybind11/operators.h>

#include "bindings.hpp"
#include "real_numbers.hpp"
#include "lrchain/params.hpp"

namespace py = pybind11;

namespace lrchain::python {

namespace {
// A parameter's value as a double: complex refused, a value that is not a number a TypeError.
double number_of(const py::handle& value, const std::string& name) {
  try {
    return real_number(value, name);
  } catch (const py::cast_error&) {
    throw py::type_error("Params: " + name + " must be a number, not " +
                         std::string(py::str(value.get_type().attr("__name__"))));
  }
}
}  // namespace

void register_params(py::module_& m) {
  py::class_<Params>(m, "Params", R"doc(
Parameters of the locally resonant granular chain (Sec. 2 of the paper), all dimensionless:
Hertz exponent alpha > 1, precompression overlap delta0 > 0, resonator spring kappa > 0 and
mass ratio rho = m2/m1 > 0. The defaults are the paper's (alpha=3/2, delta0=4/9, kappa=1,
rho=1/3). Immutable; use replace(...) for a changed copy. Invalid values raise
InvalidParameterError (a ValueError) naming the parameter and its valid range.)doc")
      .def(py::init([](const py::object& alpha, const py::object& delta0, const py::object& kappa, const py::object& rho) {
             const Params p{number_of(alpha, "alpha"), number_of(delta0, "delta0"), number_of(kappa, "kappa"),
                            number_of(rho, "rho")};
             validate(p);
             return p;
           }),
           py::kw_only(), py::arg("alpha") = 1.5, py::arg("delta0") = 4.0 / 9.0, py::arg("kappa") = 1.0,
           py::arg("rho") = 1.0 / 3.0)
      .def_readonly("alpha", &Params::alpha, "Hertz exponent alpha > 1")
      .def_readonly("delta0", &Params::delta0, "precompression overlap delta0 > 0")
      .def_readonly("kappa", &Params::kappa, "resonator spring constant kappa > 0")
      .def_readonly("rho", &Params::rho, "mass ratio rho = m2/m1 > 0")
      .def_property_readonly(
          "taylor_coefficients",
          [](const Params& p) {
            const TaylorCoefficients K = taylor_coefficients(p);
            return py::make_tuple(K.K2, K.K3, K.K4);
          },
          "(K2, K3, K4) of V(r) = K2 r^2/2 + K3 r^3/3 + K4 r^4/4 + O(r^5)")
      .def(
          "replace",
          [](const Params& p, py::kwargs changes) {
            Params q = p;
            for (auto [key, value] : changes) {
              const std::string name = py::str(key);
              const double v = number_of(value, name);
              if (name == "alpha") q.alpha = v;
              else if (name == "delta0") q.delta0 = v;
              else if (name == "kappa") q.kappa = v;
              else if (name == "rho") q.rho = v;
              else throw py::type_error("Params.replace(): unknown parameter '" + name +
                                        "' (alpha, delta0, kappa, rho)");
            }
            validate(q);
            return q;
          },
          "A copy with the given parameters changed, e.g. p.replace(rho=3).")
      .def("__eq__", [](const Params& a, const Params& b) {
        return a.alpha == b.alpha && a.delta0 == b.delta0 && a.kappa == b.kappa && a.rho == b.rho;
      })
      .def("__hash__", [](const Params& p) {
        return py::hash(py::make_tuple(p.alpha, p.delta0, p.kappa, p.rho));
      })
      .def("__repr__", [](const Params& p) {
        return fmt::format("Params(alpha={}, delta0={}, kappa={}, rho={})",
                           p.alpha, p.delta0, p.kappa, p.rho);
      })
      .def(py::pickle(
          [](const Params& p) { return py::make_tuple(p.alpha, p.delta0, p.kappa, p.rho); },
          [](const py::tuple& t) {
            const Params p{t[0].cast<double>(), t[1].cast<double>(), t[2].cast<double>(), t[3].cast<double>()};
            validate(p);
            return p;
          }));
}

}  // namespace lrchain::python

// Complex numbers refused where a real one is expected (real_numbers.hpp), and
// _lrchain.refuse_complex(value, name) for the arguments of the Python functions (_keywords.py).
#include "real_numbers.hpp"

#include "bindings.hpp"
#include "lrchain/errors.hpp"

namespace py = pybind11;

namespace lrchain::python {

namespace {
// True for Python's complex (and numpy.complex128, its subclass) and for numpy complex scalars and
// arrays (dtype kind 'c').
bool is_complex(const py::handle& value) {
  if (PyComplex_Check(value.ptr())) return true;
  if (!py::hasattr(value, "dtype")) return false;
  const py::object dtype = value.attr("dtype");
  return py::hasattr(dtype, "kind") && py::str(dtype.attr("kind")).cast<std::string>() == "c";
}
}  // namespace

void refuse_complex(const py::handle& value, const std::string& name) {
  if (is_complex(value))
    throw InvalidParameter(name, "must be real, not complex (" + std::string(py::repr(value)) +
                                     "): the imaginary part is not dropped silently; pass .real if that is meant");
  if (py::isinstance<py::list>(value) || py::isinstance<py::tuple>(value))
    for (const auto& item : value) refuse_complex(item, name);
}

double real_number(const py::handle& value, const std::string& name) {
  refuse_complex(value, name);
  return value.cast<double>();
}

void register_real_numbers(py::module_& m) {
  m.def("refuse_complex", &refuse_complex, py::arg("value"), py::arg("name"),
        "InvalidParameterError naming `name` if value is complex (or a list/tuple/array holding complex numbers).");
}

}  // namespace lrchain::python

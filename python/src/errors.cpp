// lrchain's typed C++ exceptions as the Python exceptions of lrchain.errors: InvalidParameter ->
// InvalidParameterError (a ValueError with .parameter), InputError -> InputError (ValueError),
// NumericalFailure -> NumericalFailure (RuntimeError), Interrupted -> KeyboardInterrupt.
#include <exception>

#include "bindings.hpp"
#include "lrchain/errors.hpp"

namespace py = pybind11;

namespace lrchain::python {

namespace {
// The exception classes, kept for the interpreter's lifetime (never destroyed at exit).
struct ErrorClasses {
  py::handle invalid_parameter, input_error, numerical_failure;
};
ErrorClasses* classes = nullptr;

void raise(py::handle type, py::object value) { PyErr_SetObject(type.ptr(), value.ptr()); }
}  // namespace

void register_errors(py::module_& m) {
  const py::module_ errors = py::module_::import("lrchain.errors");
  const auto keep = [&](const char* name) { return py::object(errors.attr(name)).release(); };
  classes = new ErrorClasses{keep("InvalidParameterError"), keep("InputError"), keep("NumericalFailure")};
  m.attr("InvalidParameterError") = classes->invalid_parameter;
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const InvalidParameter& e) {
      raise(classes->invalid_parameter, classes->invalid_parameter(e.what(), e.parameter()));
    } catch (const InputError& e) {
      raise(classes->input_error, classes->input_error(e.what()));
    } catch (const NumericalFailure& e) {
      raise(classes->numerical_failure, classes->numerical_failure(e.what()));
    } catch (const Interrupted& e) {
      PyErr_SetString(PyExc_KeyboardInterrupt, e.what());
    }
  });
}

}  // namespace lrchain::python

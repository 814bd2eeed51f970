#pragma once
// Complex numbers where a real one is expected: refused with InvalidParameter naming the argument,
// never truncated to the real part (numpy's complex scalars and arrays convert to float by dropping
// the imaginary part, with only a warning).
#include <string>

#include <pybind11/pybind11.h>

namespace lrchain::python {

// Throws InvalidParameter(name, ...) if `value` is a complex number (Python's complex, a numpy complex
// scalar or an array of complex dtype) or a list/tuple holding one.
void refuse_complex(const pybind11::handle& value, const std::string& name);

// `value` as a double after refuse_complex (pybind11::cast_error for a value that is not a number).
double real_number(const pybind11::handle& value, const std::string& name);

}  // namespace lrchain::python

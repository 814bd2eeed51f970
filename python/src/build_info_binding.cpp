// lrchain.__version__ and lrchain.provenance(): the build facts of `lrchain --version` (lrchain::build_info).
#include <pybind11/pybind11.h>

#include "bindings.hpp"
#include "lrchain/provenance.hpp"

namespace lrchain::python {

namespace py = pybind11;

void register_build_info(py::module_& m) {
  m.def(
      "build_info",
      [] {
        const BuildInfo b = build_info();
        py::dict d;
        d["version"] = b.version;
        d["commit"] = b.commit.empty() ? py::object(py::none()) : py::object(py::str(b.commit));
        d["compiler"] = b.compiler;
        d["build_type"] = b.build_type;
        d["version_line"] = version_line();
        return d;
      },
      "The build's version, git commit (None outside a checkout), compiler, build type and the line "
      "`lrchain --version` prints.");
}

}  // namespace lrchain::python

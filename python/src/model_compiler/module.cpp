// lrchain._model_compiler: the run-time model compiler (derivation with GiNaC, the C++ compiler,
// the per-user cache) as its own extension module, so that `import lrchain` does not load GiNaC;
// lrchain.load_model imports it for a model file that is not a shipped one.
#include <pybind11/pybind11.h>

#include <atomic>

#include "../model_capsule.hpp"
#include "lrchain/errors.hpp"
#include "lrchain/model_compiler.hpp"

namespace py = pybind11;

namespace {

constexpr const char* kStopFlagCapsuleName = "lrchain.stop_flag";

// The stop flag a caller passes as a capsule (lrchain's InterruptGuard flag), or nullptr.
const std::atomic<bool>* stop_flag(const py::object& stop) {
  if (stop.is_none()) return nullptr;
  return static_cast<const std::atomic<bool>*>(PyCapsule_GetPointer(stop.ptr(), kStopFlagCapsuleName));
}

// The model file the caller's loader read (a capsule borrowing its ModelFileContent).
const lrchain::ModelFileContent& model_file(const py::object& file) {
  const void* p = PyCapsule_GetPointer(file.ptr(), lrchain::python::kModelFileCapsuleName);
  if (!p) throw py::error_already_set();
  return *static_cast<const lrchain::ModelFileContent*>(p);
}

// Stopped by the caller's flag (SIGINT): KeyboardInterrupt, unless a Python signal handler raised.
[[noreturn]] void raise_interrupted(const lrchain::Interrupted& e) {
  if (PyErr_CheckSignals() != 0) throw py::error_already_set();
  PyErr_SetString(PyExc_KeyboardInterrupt, e.what());
  throw py::error_already_set();
}

// A bad model file: lrchain.InputError (a ValueError).
[[noreturn]] void raise_input_error(const lrchain::InputError& e) {
  const py::object input_error = py::module_::import("lrchain.errors").attr("InputError");
  PyErr_SetString(input_error.ptr(), e.what());
  throw py::error_already_set();
}

template <class Handle>
py::capsule handle_capsule(Handle handle, const char* name) {
  return py::capsule(new Handle(std::move(handle)), name, [](PyObject* capsule) {
    delete static_cast<Handle*>(PyCapsule_GetPointer(capsule, PyCapsule_GetName(capsule)));
  });
}

// The model file `file` (as the loader read it) compiled once into the per-user cache (or found
// there) and loaded: (definition capsule, lattice kernels capsule or None, from_cache, library)
// (model_capsule.hpp). A bad model file raises lrchain.InputError (a ValueError); a missing or
// failing compiler RuntimeError. Without a compiler (the GiNaC fallback, no kernels) it warns
// (RuntimeWarning) as the CLI does on stderr. The GIL is released only around the C++ compile path,
// which touches no Python object and holds the process-wide lock of the symbolic engine itself
// (model_compiler.hpp). `stop` (a capsule of the caller's SIGINT flag) is polled while deriving and
// compiling: KeyboardInterrupt.
py::tuple compile(const py::object& file, const py::object& stop) {
  const lrchain::ModelFileContent& content = model_file(file);
  lrchain::CompiledModel compiled;
  lrchain::CompiledModelInfo info;
  const std::atomic<bool>* flag = stop_flag(stop);
  try {
    py::gil_scoped_release release;  // deriving and compiling takes seconds
    compiled = lrchain::compile_model(content, &info, flag);
  } catch (const lrchain::Interrupted& e) {
    raise_interrupted(e);
  } catch (const lrchain::InputError& e) {
    raise_input_error(e);
  }
  if (!info.fallback_reason.empty() &&
      PyErr_WarnEx(PyExc_RuntimeWarning, lrchain::model_fallback_warning(compiled.definition->name, info).c_str(), 2) != 0)
    throw py::error_already_set();
  const py::object kernels = compiled.kernels
                                 ? py::object(handle_capsule(lrchain::python::LatticeKernelsHandle(compiled.kernels),
                                                             lrchain::python::kLatticeCapsuleName))
                                 : py::object(py::none());
  return py::make_tuple(handle_capsule(lrchain::python::ModelDefinitionHandle(compiled.definition), lrchain::python::kModelCapsuleName),
                        kernels, info.from_cache, info.library.string());
}

// Raises the lrchain.InputError that says why the model file has no lattice kernels (no compiler,
// or force laws a lattice cannot run).
void refuse_lattice(const py::object& file, const py::object& stop) {
  const lrchain::ModelFileContent& content = model_file(file);
  const std::atomic<bool>* flag = stop_flag(stop);
  try {
    py::gil_scoped_release release;
    lrchain::compile_model_lattice(content, nullptr, flag);
  } catch (const lrchain::Interrupted& e) {
    raise_interrupted(e);
  } catch (const lrchain::InputError& e) {
    raise_input_error(e);
  }
}

// Raises lrchain.InputError when the lattice code of `file` is neither cached nor compilable.
void check_lattice(const py::object& file, const py::object&) {
  try {
    lrchain::check_lattice_compiler(model_file(file));
  } catch (const lrchain::InputError& e) {
    raise_input_error(e);
  }
}

}  // namespace

PYBIND11_MODULE(_model_compiler, m) {
  m.doc() = "Run-time compiler of lattice model files for lrchain.load_model (GiNaC, the C++ compiler).";
  m.def("compile", &compile, py::arg("file"), py::arg("stop") = py::none(),
        "The model file (a capsule of the file lrchain's loader read) derived, compiled into the per-user cache "
        "(one object: evaluators and lattice kernels) and loaded: (model capsule, kernels capsule or None, "
        "from_cache, library). stop: a capsule of lrchain's SIGINT flag, polled while deriving and compiling.");
  m.def("refuse_lattice", &refuse_lattice, py::arg("file"), py::arg("stop") = py::none(),
        "Raises lrchain.InputError saying why the compiled model file has no lattice kernels.");
  m.def("check_lattice", &check_lattice, py::arg("file"), py::arg("stop") = py::none(),
        "Raises lrchain.InputError when the lattice code of the model file can be neither found in the cache nor "
        "compiled.");
  m.attr("compiler") = lrchain::model_compiler_path();
}

// lrchain.load_model and lrchain.Model: a lattice model file (docs/models.md) with parameter values,
// and the batch NLS coefficients of its branches. The model loader (jobs::ModelSource) finds a
// shipped model by name or by the bytes of its file; any other file is derived and compiled at run
// time by lrchain._model_compiler (imported only then), cached per user.
#include <atomic>
#include <fmt/format.h>
#include <memory>
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "coefficient_arrays.hpp"
#include "interrupt_guard.hpp"
#include "lrchain/coefficients_batch.hpp"
#include "lrchain/dispersion.hpp"
#include "lrchain/errors.hpp"
#include "lrchain/jobs/model_source.hpp"
#include "lrchain/model.hpp"
#include "lrchain/model_json.hpp"
#include "loaded_model.hpp"
#include "model_capsule.hpp"
#include "real_numbers.hpp"

namespace py = pybind11;

namespace lrchain::python {

namespace {

#ifdef LRCHAIN_WITH_MODEL_COMPILER
// lrchain._model_compiler as the model loader calls it (with the GIL; the compiler releases it).
// Ctrl-C while deriving or compiling stops the compile (its compiler's process group killed) and
// KeyboardInterrupt follows.
class PythonModelCompiler final : public jobs::ModelCompiler {
 public:
  jobs::CompiledCode compile(const ModelFileContent& file) const override {
    const py::tuple compiled = call("compile", file);
    jobs::CompiledCode code;
    code.definition = *static_cast<ModelDefinitionHandle*>(PyCapsule_GetPointer(compiled[0].ptr(), kModelCapsuleName));
    if (!compiled[1].is_none())
      code.kernels = *static_cast<LatticeKernelsHandle*>(PyCapsule_GetPointer(compiled[1].ptr(), kLatticeCapsuleName));
    code.from_cache = compiled[2].cast<bool>();
    code.library = compiled[3].cast<std::string>();
    return code;
  }
  void refuse_lattice(const ModelFileContent& file) const override { call("refuse_lattice", file); }
  void check_lattice(const ModelFileContent& file) const override { call("check_lattice", file); }

 private:
  // lrchain._model_compiler.<function>(file, stop) with the SIGINT flag as `stop`.
  static py::object call(const char* function, const ModelFileContent& file) {
    InterruptGuard guard;
    const py::capsule stop(const_cast<std::atomic<bool>*>(guard.flag()), "lrchain.stop_flag");
    const py::capsule content(static_cast<const void*>(&file), kModelFileCapsuleName);
    py::object result = py::module_::import("lrchain._model_compiler").attr(function)(content, stop);
    guard.raise_if_interrupted();
    return result;
  }
};
#endif

// The compiler the model loader gets: none in a build without the model compiler.
std::shared_ptr<const jobs::ModelCompiler> model_compiler() {
#ifdef LRCHAIN_WITH_MODEL_COMPILER
  return std::make_shared<const PythonModelCompiler>();
#else
  return nullptr;
#endif
}

std::vector<std::pair<std::string, double>> parameter_values(const py::kwargs& parameters) {
  std::vector<std::pair<std::string, double>> values;
  for (auto [key, value] : parameters) {
    const std::string name = py::str(key);
    if (!py::isinstance<py::float_>(value) && !py::isinstance<py::int_>(value) &&
        !py::hasattr(value, "__float__"))
      throw InvalidParameter(name, "must be a number");
    values.emplace_back(name, real_number(value, name));  // a complex value is refused, not truncated
  }
  return values;
}

LoadedModel load_model(const py::object& source_path, const py::kwargs& parameters) {
  const std::string source = py::str(py::module_::import("os").attr("fspath")(source_path));
  const auto values = parameter_values(parameters);
  auto loaded = std::make_shared<const jobs::ModelSource>(source, "load_model:", model_compiler());
  return LoadedModel{loaded, loaded->model(values)};
}

// The branch index of `branch`; the resonant chain also takes the spellings of its Branch ('opt', '+', ...).
Index branch_index(const Model& model, const std::string& branch) {
  return model.resonant_chain_params() ? model.branch(to_string(parse_branch(branch))) : model.branch(branch);
}

// The coefficients of every wavenumber of theta on the named branch: lib's coefficients_batch (the
// resonant chain through its vectorised loop) without the GIL.
py::dict model_coefficient_arrays(const LoadedModel& loaded, const std::string& branch, const Thetas& theta,
                                  const py::object& out_arrays) {
  const Model& model = loaded.model;
  const Index b = branch_index(model, branch);
  validate_wavenumbers(theta);
  // The chain's own message for its zero-frequency mode, as lrchain.coefficients(Params) gives it.
  if (model.resonant_chain_params() && model.resonant_chain_branch(b) == Branch::acoustic)
    for (py::ssize_t i = 0; i < theta.size(); ++i)
      if (theta.data()[i] == 0.0) {
        try {
          check_resonant_chain_wavenumber(Branch::acoustic, 0.0);
        } catch (const InvalidParameter& e) {
          const std::string failure = e.what();
          throw InvalidParameter("theta", failure.substr(failure.find(": ") + 2) + wavenumber_position(theta, i));
        }
      }
  CoefficientArrays out(shape_of(theta), out_arrays);
  std::ptrdiff_t refused = -1;
  std::string failure, failed_parameter;
  {
    py::gil_scoped_release release;
    try {
      coefficients_batch(model, b, {theta.data(), static_cast<std::size_t>(theta.size())}, out.columns, &refused);
    } catch (const InvalidParameter& e) {
      failure = e.what();
      failed_parameter = e.parameter();  // theta, or the model parameter that makes the evaluation fail
    }
  }
  if (!failed_parameter.empty())
    throw InvalidParameter(failed_parameter, failure.substr(failure.find(": ") + 2) + wavenumber_position(theta, refused));
  return out.to_dict();
}

py::dict parameter_dict(const Model& m) {
  py::dict d;
  const auto& parameters = m.definition().parameters;
  for (std::size_t i = 0; i < parameters.size(); ++i) d[py::str(parameters[i].name)] = m.inputs()[i];
  return d;
}

}  // namespace

const lrchain_lattice_kernels& lattice_kernels(const LoadedModel& m) { return *m.source->lattice().kernels; }

nlohmann::json model_summary_json(const LoadedModel& m) {
  nlohmann::json j = model_json(m.model);
  j["lattice_code"] = jobs::lattice_code_json(m.source->lattice(), false);
  return j;
}

void register_model(py::module_& m) {
  py::class_<LoadedModel>(m, "Model", R"doc(
A lattice model (a model file, docs/models.md) with parameter values; made by lrchain.load_model.
name, description, parameters ({name: value}), ranges ({name: range text}), branches (names in
increasing frequency), mean_flow (False for on-site models: no lambda), file_hash. Immutable; use
replace(...) for a copy with other parameter values. Model(source, **parameters) is
lrchain.load_model(source, **parameters).)doc")
      .def(py::init(&load_model), py::arg("source"))
      .def_property_readonly("name", [](const LoadedModel& l) { return l.model.name(); })
      .def_property_readonly("description", [](const LoadedModel& l) { return l.definition().description; })
      .def_property_readonly("file_hash", [](const LoadedModel& l) { return model_hash_text(l.model.file_hash()); },
                             "FNV-1a 64 of the model file's bytes, as 0x + 16 hex digits")
      .def_property_readonly("parameters", [](const LoadedModel& l) { return parameter_dict(l.model); })
      .def_property_readonly("ranges",
                             [](const LoadedModel& l) {
                               py::dict d;
                               for (const auto& q : l.definition().parameters) d[py::str(q.name)] = q.range_text;
                               return d;
                             })
      .def_property_readonly("branches", [](const LoadedModel& l) { return py::tuple(py::cast(l.definition().branch_names)); })
      .def_property_readonly("mean_flow", [](const LoadedModel& l) { return l.definition().mean_flow; })
      .def_property_readonly(
          "params",
          [](const LoadedModel& l) -> py::object {
            if (!l.model.resonant_chain_params()) return py::none();
            return py::cast(*l.model.resonant_chain_params());
          },
          "lrchain.Params of the resonant chain (for lrchain.simulate and lrchain.dark), None for other models")
      .def(
          "replace",
          [](const LoadedModel& l, const py::kwargs& changes) {
            auto values = parameter_values(changes);
            const auto& parameters = l.definition().parameters;
            std::vector<std::pair<std::string, double>> all;
            for (std::size_t i = 0; i < parameters.size(); ++i) all.emplace_back(parameters[i].name, l.model.inputs()[i]);
            for (auto& v : values) all.push_back(std::move(v));
            return LoadedModel{l.source, l.source->model(all)};
          },
          "A copy with the given parameters changed, e.g. m.replace(w0=2).")
      .def("__repr__", [](const LoadedModel& l) {
        std::string text;
        for (auto [name, value] : parameter_dict(l.model))
          text += fmt::format(", {}={}", std::string(py::str(name)), value.cast<double>());
        return fmt::format("Model('{}'{})", l.model.name(), text);
      });
  m.def("load_model", &load_model, py::arg("source"),
        "The model of a file (or a shipped model's name) with parameters overriding its defaults.");
  m.def("model_coefficients_array", &model_coefficient_arrays, py::arg("model"), py::arg("branch"), py::arg("theta"),
        py::arg("out") = py::none(),
        "NLS coefficients of a model's branch at every wavenumber of theta: {name: array}; regime as int8 codes.");
  py::list names;
  for (const auto& d : shipped_models()) names.append(d.name);
  m.attr("shipped_models") = py::tuple(names);
}

}  // namespace lrchain::python

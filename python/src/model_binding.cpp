// lrchain.load_model and lrchain.Model: a lattice model file (docs/models.md) with parameter values,
// and the batch NLS coefficients of its branches. A shipped model is found by name or by the bytes
// of its file; any other file is derived and compiled at run time by the model compiler (as
// `lrchain coeffs --model FILE` does), cached per user.
#include <filesystem>
#include <fmt/format.h>
#include <memory>
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "coefficient_arrays.hpp"
#include "interrupt_guard.hpp"
#include "lrchain/errors.hpp"
#include "lrchain/model.hpp"
#include "lrchain/model_json.hpp"
#include "lrchain/sha256.hpp"
#include "loaded_model.hpp"
#include "lrchain/sim/model_lattice_bloch.hpp"
#include "model_capsule.hpp"
#include "real_numbers.hpp"

namespace py = pybind11;
namespace fs = std::filesystem;

namespace lrchain::python {

namespace {

// Shipped definitions live for the whole program: shared without owning.
std::shared_ptr<const ModelDefinition> shipped(const ModelDefinition* d) {
  return std::shared_ptr<const ModelDefinition>(std::shared_ptr<const ModelDefinition>(), d);
}

std::string shipped_names() {
  std::string names;
  for (const auto& m : shipped_models()) names += (names.empty() ? "" : ", ") + m.name;
  return names;
}

// The shipped definition of `source`: a shipped model's name or a file whose bytes are a shipped
// model file's; nullptr for any other readable file (called without the GIL).
std::shared_ptr<const ModelDefinition> find_shipped_definition(const std::string& source) {
  const fs::path path(source);
  const bool bare_name = !source.empty() && !path.has_parent_path() && !path.has_extension();
  if (bare_name && !fs::exists(path)) {
    if (const ModelDefinition* d = find_shipped_model(source)) return shipped(d);
    throw InputError("load_model: no shipped model '" + source + "' (shipped: " + shipped_names() +
                     ") and no such file");
  }
  std::string bytes;
  try {
    bytes = read_model_file_bytes(source);
  } catch (const InputError& e) {
    throw InputError(std::string("load_model: ") + e.what());
  }
  const ModelDefinition* d = find_shipped_model_by_bytes(bytes);
  return d ? shipped(d) : nullptr;
}

// A user's model file derived and compiled at run time by lrchain._model_compiler (with the GIL;
// the compiler releases it).
std::shared_ptr<const ModelDefinition> compile_user_model(const std::string& source) {
#ifdef LRCHAIN_WITH_MODEL_COMPILER
  // Ctrl-C while deriving or compiling: the compile stops (its compiler's process group killed) and
  // KeyboardInterrupt follows.
  InterruptGuard guard;
  const py::capsule stop(const_cast<std::atomic<bool>*>(guard.flag()), "lrchain.stop_flag");
  const py::object capsule = py::module_::import("lrchain._model_compiler").attr("compile")(source, stop);
  guard.raise_if_interrupted();
  return *static_cast<ModelDefinitionHandle*>(PyCapsule_GetPointer(capsule.ptr(), kModelCapsuleName));
#else
  throw InputError("load_model: " + source + ": not a shipped model file, and this build has no model compiler "
                   "(configure with LRCHAIN_BUILD_DERIVATION=ON)");
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
  std::shared_ptr<const ModelDefinition> definition;
  {
    py::gil_scoped_release release;
    definition = find_shipped_definition(source);
  }
  if (!definition) definition = compile_user_model(source);
  const fs::path path(source);
  const bool bare_name = !path.has_parent_path() && !path.has_extension() && !fs::exists(path);
  return LoadedModel{definition, Model(definition, values), bare_name ? std::string() : fs::absolute(path).string()};
}

// The lattice code of a user's model file, compiled at run time by lrchain._model_compiler.
std::shared_ptr<const lrchain_lattice_kernels> compile_user_lattice(const LoadedModel& m) {
#ifdef LRCHAIN_WITH_MODEL_COMPILER
  std::string bytes;
  try {
    bytes = read_model_file_bytes(m.source);
  } catch (const InputError&) {
  }
  if (bytes.empty() || sha256_hex(bytes) != m.definition->file_sha256)
    throw InputError("model " + m.model.name() + ": the file " + m.source +
                     " changed (or went) since it was loaded; load it again with lrchain.load_model");
  const py::tuple compiled = py::module_::import("lrchain._model_compiler").attr("compile_lattice")(m.source);
  m.lattice_compiled_in = false;
  m.lattice_from_cache = compiled[1].cast<bool>();
  m.lattice_library = compiled[2].cast<std::string>();
  return *static_cast<LatticeKernelsHandle*>(PyCapsule_GetPointer(compiled[0].ptr(), kLatticeCapsuleName));
#else
  throw InputError("model " + m.model.name() + ": not a shipped model file, and this build has no model compiler for "
                   "its lattice code (configure with LRCHAIN_BUILD_DERIVATION=ON)");
#endif
}

bool is_resonant_chain(const ModelDefinition& d) {
  const ModelDefinition* shipped = find_shipped_model("resonant_chain");
  return shipped && d.file_sha256 == shipped->file_sha256;
}

Params resonant_chain_params(const Model& m) {
  return Params{m.parameter("alpha"), m.parameter("delta0"), m.parameter("kappa"), m.parameter("rho")};
}

// The coefficients of every wavenumber of theta on the named branch. The shipped resonant chain
// goes through its specialised evaluators (bit-identical to Params), as `lrchain coeffs --model` does.
py::dict model_coefficient_arrays(const LoadedModel& loaded, const std::string& branch, const Thetas& theta,
                                  const py::object& out_arrays) {
  const Model& model = loaded.model;
  if (is_resonant_chain(model.definition()))
    return resonant_chain_coefficient_arrays(resonant_chain_params(model), branch, theta, out_arrays);
  const Index b = model.branch(branch);
  validate_wavenumbers(theta);
  CoefficientArrays out(shape_of(theta), out_arrays);
  const double* t = theta.data();
  const py::ssize_t n = theta.size();
  py::ssize_t failed = -1;
  std::string failure, failed_parameter;
  {
    py::gil_scoped_release release;
    for (py::ssize_t i = 0; i < n && failed < 0; ++i) {
      try {
        out.store(i, coefficients(model, b, t[i]));
      } catch (const InvalidParameter& e) {
        failed = i;
        failure = e.what();
        failed_parameter = e.parameter();  // theta, or the model parameter that makes the evaluation fail
      }
    }
  }
  if (failed >= 0)
    throw InvalidParameter(failed_parameter, failure.substr(failure.find(": ") + 2) + wavenumber_position(theta, failed));
  return out.to_dict();
}

py::dict parameter_dict(const Model& m) {
  py::dict d;
  const auto& parameters = m.definition().parameters;
  for (std::size_t i = 0; i < parameters.size(); ++i) d[py::str(parameters[i].name)] = m.inputs()[i];
  return d;
}

}  // namespace

const lrchain_lattice_kernels& lattice_kernels(const LoadedModel& m) {
  if (!m.lattice) {
    if (const lrchain_lattice_kernels* shipped = sim::compiled_in_lattice_kernels(m.model))
      m.lattice = std::shared_ptr<const lrchain_lattice_kernels>(std::shared_ptr<const lrchain_lattice_kernels>(), shipped);
    else
      m.lattice = compile_user_lattice(m);
    if (std::size_t(m.lattice->parameter_count) != m.definition->parameters.size())
      throw std::runtime_error("the lattice code of model " + m.model.name() + " takes " +
                               std::to_string(m.lattice->parameter_count) + " parameters, its evaluators " +
                               std::to_string(m.definition->parameters.size()));
  }
  return *m.lattice;
}

nlohmann::json model_summary_json(const LoadedModel& m) {
  nlohmann::json code{{"compiled_in", m.lattice_compiled_in}};
  code["from_cache"] = m.lattice_compiled_in ? nlohmann::json(nullptr) : nlohmann::json(m.lattice_from_cache);
  code["library"] = m.lattice_compiled_in ? nlohmann::json(nullptr) : nlohmann::json(m.lattice_library);
  nlohmann::json j = model_json(m.model);
  j["lattice_code"] = code;
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
      .def_property_readonly("description", [](const LoadedModel& l) { return l.definition->description; })
      .def_property_readonly("file_hash", [](const LoadedModel& l) { return model_hash_text(l.model.file_hash()); },
                             "FNV-1a 64 of the model file's bytes, as 0x + 16 hex digits")
      .def_property_readonly("parameters", [](const LoadedModel& l) { return parameter_dict(l.model); })
      .def_property_readonly("ranges",
                             [](const LoadedModel& l) {
                               py::dict d;
                               for (const auto& q : l.definition->parameters) d[py::str(q.name)] = q.range_text;
                               return d;
                             })
      .def_property_readonly("branches", [](const LoadedModel& l) { return py::tuple(py::cast(l.definition->branch_names)); })
      .def_property_readonly("mean_flow", [](const LoadedModel& l) { return l.definition->mean_flow; })
      .def_property_readonly(
          "params",
          [](const LoadedModel& l) -> py::object {
            if (!is_resonant_chain(*l.definition)) return py::none();
            return py::cast(resonant_chain_params(l.model));
          },
          "lrchain.Params of the resonant chain (for lrchain.simulate and lrchain.dark), None for other models")
      .def(
          "replace",
          [](const LoadedModel& l, const py::kwargs& changes) {
            auto values = parameter_values(changes);
            const auto& parameters = l.definition->parameters;
            std::vector<std::pair<std::string, double>> all;
            for (std::size_t i = 0; i < parameters.size(); ++i) all.emplace_back(parameters[i].name, l.model.inputs()[i]);
            for (auto& v : values) all.push_back(std::move(v));
            return LoadedModel{l.definition, Model(l.definition, all), l.source};
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

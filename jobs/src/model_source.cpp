// The one model loader (lrchain/jobs/model_source.hpp): name or file -> shipped definition or
// compiled artifact (evaluators and lattice kernels in one object), the file read and hashed once.
#include "lrchain/jobs/model_source.hpp"

#include <chrono>
#include <filesystem>
#include <stdexcept>

#include "lrchain/errors.hpp"
#include "lrchain/sim/model_lattice.hpp"

namespace lrchain::jobs {

namespace {

// Shipped definitions live for the whole program: shared without owning.
std::shared_ptr<const ModelDefinition> unowned(const ModelDefinition* d) {
  return std::shared_ptr<const ModelDefinition>(std::shared_ptr<const ModelDefinition>(), d);
}

std::string shipped_names() {
  std::string names;
  for (const auto& m : shipped_models()) names += (names.empty() ? "" : ", ") + m.name;
  return names;
}

// A shipped model's name rather than a path: no directory, no extension, and no such file.
bool names_a_shipped_model(const std::string& source) {
  const std::filesystem::path path(source);
  std::error_code ec;
  return !source.empty() && !path.has_parent_path() && !path.has_extension() && !std::filesystem::exists(path, ec);
}

// The shipped definition `name`, or InputError after `label` naming the shipped ones.
std::shared_ptr<const ModelDefinition> shipped_definition(const std::string& name, const std::string& label) {
  const ModelDefinition* d = find_shipped_model(name);
  if (!d) throw InputError(label + " no shipped model '" + name + "' (shipped: " + shipped_names() + ") and no such file");
  return unowned(d);
}

std::string no_compiler(const std::string& label, const std::string& path, const std::string& what) {
  return label + " " + path + ": not a shipped model file, and this build has no model compiler" + what +
         " (configure with LRCHAIN_BUILD_DERIVATION=ON)";
}

}  // namespace

nlohmann::json lattice_code_json(const LatticeCode& code, bool timed) {
  nlohmann::json j{{"compiled_in", code.compiled_in}};
  if (timed) j["seconds"] = code.seconds;
  j["from_cache"] = code.compiled_in ? nlohmann::json(nullptr) : nlohmann::json(code.from_cache);
  j["library"] = code.compiled_in ? nlohmann::json(nullptr) : nlohmann::json(code.library);
  return j;
}

ModelSource::ModelSource(const std::string& source, const std::string& label, std::shared_ptr<const ModelCompiler> compiler,
                         bool lattice_run)
    : label_(label), compiler_(std::move(compiler)) {
  if (names_a_shipped_model(source)) {
    definition_ = shipped_definition(source, label_);
    return;
  }
  try {
    file_ = read_model_file(source);
  } catch (const InputError& e) {
    throw InputError(label_ + " " + e.what());
  }
  if (const ModelDefinition* d = find_shipped_model_by_sha256(file_.sha256)) {
    definition_ = unowned(d);
    return;
  }
  if (!compiler_) throw InputError(no_compiler(label_, file_.path, ""));
  if (lattice_run) compiler_->check_lattice(file_);
  const auto start = std::chrono::steady_clock::now();
  compiled_ = compiler_->compile(file_);
  compile_seconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  definition_ = compiled_.definition;
}

ModelSource ModelSource::shipped(const std::string& name, const std::string& label) {
  ModelSource source;
  source.label_ = label;
  source.definition_ = shipped_definition(name, label);
  return source;
}

const LatticeCode& ModelSource::lattice() const {
  if (lattice_) return *lattice_;
  const auto start = std::chrono::steady_clock::now();
  auto code = std::make_shared<LatticeCode>();
  const lrchain_lattice_kernels* compiled_in = sim::shipped_lattice_kernels(definition_->name);
  const ModelDefinition* shipped_definition = find_shipped_model(definition_->name);
  if (compiled_in && shipped_definition && shipped_definition->file_sha256 == definition_->file_sha256) {
    code->kernels = std::shared_ptr<const lrchain_lattice_kernels>(std::shared_ptr<const lrchain_lattice_kernels>(), compiled_in);
  } else {
    if (!compiler_) throw InputError(no_compiler(label_, file_.path, " for its lattice code"));
    if (!compiled_.kernels) {
      compiler_->refuse_lattice(file_);
      throw std::runtime_error(label_ + " " + file_.path + ": compiled without lattice kernels");
    }
    code->kernels = compiled_.kernels;
    code->compiled_in = false;
    code->from_cache = compiled_.from_cache;
    code->library = compiled_.library;
  }
  if (std::size_t(code->kernels->parameter_count) != definition_->parameters.size())
    throw std::runtime_error("the lattice code of model " + definition_->name + " takes " +
                             std::to_string(code->kernels->parameter_count) + " parameters, its evaluators " +
                             std::to_string(definition_->parameters.size()));
  code->seconds = compile_seconds_ + std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  lattice_ = std::move(code);
  return *lattice_;
}

}  // namespace lrchain::jobs

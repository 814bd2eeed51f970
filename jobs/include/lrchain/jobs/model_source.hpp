#pragma once
// The one model loader of every front end (docs/models.md): a shipped model by name, or a model file
// read and hashed once — a shipped model's bytes give the shipped definition, any other file is
// compiled at run time into the per-user cache by a ModelCompiler the front end injects (it links
// GiNaC; lib and jobs never do). The loaded source hands out the coefficient evaluators
// (definition()) and the lattice kernels (lattice()) of one compiled artifact.
#include <memory>
#include <string>

#include <nlohmann/json.hpp>

#include "lrchain/model.hpp"
#include "lrchain/compiled_model_abi.h"

namespace lrchain::jobs {

// A model file compiled at run time (one shared object, one cache entry): its evaluators and its
// lattice kernels together, and where the object was found.
struct CompiledCode {
  std::shared_ptr<const ModelDefinition> definition;
  std::shared_ptr<const lrchain_lattice_kernels> kernels;  // null: none (GiNaC fallback, or a force law a lattice cannot run)
  bool from_cache = false;  // the shared object existed already
  std::string library;      // the cached shared object (empty for the GiNaC fallback)
};

// The run-time model compiler as a front end provides it (the CLI calls lrchain_model_compiler
// directly, Python through lrchain._model_compiler), with that front end's stop handling, progress
// and warnings. Every call gets the file as the loader read it; none reads it again.
class ModelCompiler {
 public:
  virtual ~ModelCompiler() = default;
  // The model file compiled once into the cache (or found there): evaluators and lattice kernels
  // (the GiNaC fallback with a warning, and no kernels, when no compiler is installed).
  virtual CompiledCode compile(const ModelFileContent& file) const = 0;
  // Why a compiled file has no lattice kernels: throws that InputError (no compiler, or a force law
  // a lattice cannot run).
  virtual void refuse_lattice(const ModelFileContent& file) const = 0;
  // InputError when its lattice code is neither cached nor compilable (no compiler installed).
  virtual void check_lattice(const ModelFileContent& file) const = 0;
};

// A model's lattice kernels and where they came from (the JSON "lattice_code").
struct LatticeCode {
  std::shared_ptr<const lrchain_lattice_kernels> kernels;  // keeps a run-time compiled library loaded
  bool compiled_in = true;  // a shipped model; else compiled at run time into the model cache
  bool from_cache = false;  // run time: the cached library existed already
  std::string library;      // run time: the cached shared object
  double seconds = 0;       // time to find, compile and load the model (evaluators and kernels)
};

// {"compiled_in", "from_cache", "library"} of `code`, and "seconds" when `timed`.
nlohmann::json lattice_code_json(const LatticeCode& code, bool timed = true);

class ModelSource {
 public:
  // The model `source` names: a shipped model's name (no directory, no extension, and no such file)
  // or a model file's path. `label` starts every InputError message (e.g. "--model",
  // "load_model:"). `compiler` may be null (a build without the model compiler): a user's file is
  // then refused. With `lattice_run`, a user's file whose lattice code can be neither found in the
  // cache nor compiled is refused before its evaluators are compiled.
  ModelSource(const std::string& source, const std::string& label, std::shared_ptr<const ModelCompiler> compiler,
              bool lattice_run = false);
  // The shipped model `name` whatever files exist (InputError after `label` naming the shipped ones).
  static ModelSource shipped(const std::string& name, const std::string& label);

  // The definition (evaluators, parameters, branches): shared by every Model made from it.
  const std::shared_ptr<const ModelDefinition>& definition() const { return definition_; }
  // The file's path as given; empty for a shipped model given by name.
  const std::string& path() const { return file_.path; }
  // The model with `values` (NAME, value) overriding the file's defaults.
  Model model(const std::vector<std::pair<std::string, double>>& values) const { return Model(definition_, values); }

  // The lattice kernels of the model: a shipped model's compiled-in kernels, else those of the
  // file's compiled object. InputError when there are none (no model compiler, no C++ compiler, or
  // force laws a lattice cannot run). Not thread-safe (a front end calls it from one thread at a time).
  const LatticeCode& lattice() const;

 private:
  ModelSource() = default;
  std::string label_;
  ModelFileContent file_;  // empty for a shipped model given by name
  std::shared_ptr<const ModelCompiler> compiler_;
  std::shared_ptr<const ModelDefinition> definition_;
  mutable std::shared_ptr<const LatticeCode> lattice_;
  CompiledCode compiled_;  // a user's file: the compiled object
  double compile_seconds_ = 0;
};

}  // namespace lrchain::jobs

#pragma once
// Run-time compilation of a user's model file (docs/models.md): derive it, emit its evaluators as
// C++, compile them with the compiler lrchain was built with into a per-user cache
// ($XDG_CACHE_HOME/lrchain, default ~/.cache/lrchain) keyed by a SHA-256 of the file's bytes, the
// compiler and its version, the lrchain version and the kind of code, and load the shared object
// once the cache and the object pass their checks (model_cache.hpp). A second call with the same
// file reuses it. Every function here holds derivation::symbolic_engine_mutex() (GiNaC is not
// thread-safe), so any front end may call them from several threads.
#include <atomic>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <string>

#include "lrchain/model.hpp"
#include "lrchain/compiled_model_abi.h"

namespace lrchain {

struct CompiledModelInfo {
  bool from_cache = false;        // the shared object existed already
  std::filesystem::path library;  // the cached shared object (empty for the GiNaC fallback)
  std::string fallback_reason;    // non-empty: no compiler, evaluated through GiNaC in double precision
};

// A model file compiled at run time (lrchain/compiled_model_abi.h): one shared object, one cache
// entry, holding its NLS evaluators and its lattice kernels.
struct CompiledModel {
  std::shared_ptr<const ModelDefinition> definition;
  // Null when the model has none: the GiNaC fallback (no compiler), or force laws a lattice cannot
  // run (compile_model_lattice says why). Keeps the library loaded.
  std::shared_ptr<const lrchain_lattice_kernels> kernels;
};

// Called with each step of a compile that is not found in the cache (deriving, emitting, compiling).
using CompileProgress = std::function<void(const std::string& step)>;

// The model of the file the model loader read and hashed (read_model_file; not read again): found
// in the per-user cache, or derived, emitted as two translation units (evaluators, lattice kernels)
// compiled at once and linked into one object in the cache, and loaded. When the compiler is not
// installed, the derived expressions are evaluated by GiNaC in double precision instead and there
// are no lattice kernels (info->fallback_reason says so).
// Throws InputError for a bad model file (a failing derivation check included) or an unsafe cache
// directory, and std::runtime_error when the compiler fails (InputError naming LRCHAIN_MODEL_CXX
// when that variable chose it). `stop` (e.g. a SIGINT flag) is polled between the derivation's
// steps and while the compiler runs (its whole process group is killed): then lrchain::Interrupted
// (SIGINT) is thrown and nothing is left in the cache.
CompiledModel compile_model(const ModelFileContent& content, CompiledModelInfo* info = nullptr,
                            const std::atomic<bool>* stop = nullptr, const CompileProgress& progress = {});

// compile_model(...).definition of the file at `path`, or of a file the loader read.
std::shared_ptr<const ModelDefinition> compile_model_file(const std::filesystem::path& path,
                                                          CompiledModelInfo* info = nullptr,
                                                          const std::atomic<bool>* stop = nullptr);
std::shared_ptr<const ModelDefinition> compile_model_file(const ModelFileContent& content,
                                                          CompiledModelInfo* info = nullptr,
                                                          const std::atomic<bool>* stop = nullptr);

// compile_model(...).kernels, never null: InputError when the compiler is not installed (no slow
// fallback for lattice runs) or the force laws cannot be run as a lattice.
std::shared_ptr<const lrchain_lattice_kernels> compile_model_lattice(const std::filesystem::path& path,
                                                                     CompiledModelInfo* info = nullptr,
                                                                     const std::atomic<bool>* stop = nullptr);
std::shared_ptr<const lrchain_lattice_kernels> compile_model_lattice(const ModelFileContent& content,
                                                                     CompiledModelInfo* info = nullptr,
                                                                     const std::atomic<bool>* stop = nullptr);

// Throws the InputError of compile_model_lattice when the model of `path` is not cached and the
// compiler is not installed: lattice runs call it before anything else.
void check_lattice_compiler(const std::filesystem::path& path);
void check_lattice_compiler(const ModelFileContent& content);

// Kind of the cached code, part of the cache key: "compiled model V" with V the
// LRCHAIN_COMPILED_MODEL_ABI_VERSION of lrchain/compiled_model_abi.h (the emitted evaluators'
// functions and outputs and the kernel table), so an object of an older emitter or ABI (the old
// kinds "evaluators 4" and "lattice 3" included) is never loaded.
std::string compiled_model_code_kind();

// The cache key of a model file's bytes compiled by `compiler` (its path and version line) for
// lrchain `version` into `kind` of code (compiled_model_code_kind()): the SHA-256 (64
// hex digits) of the four as length-prefixed fields.
std::string model_cache_key(const std::string& bytes, const std::string& compiler, const std::string& version,
                            const std::string& kind);
// The lrchain version the cache keys use (the project's version at build time).
std::string model_compiler_version();

// The compiler: $LRCHAIN_MODEL_CXX if set, else the one recorded at configure time; and whether it
// can be run.
std::string model_compiler_path();
bool model_compiler_available();

// The warning every front end gives when `info` says the model was not compiled (fallback_reason).
std::string model_fallback_warning(const std::string& model_name, const CompiledModelInfo& info);

}  // namespace lrchain

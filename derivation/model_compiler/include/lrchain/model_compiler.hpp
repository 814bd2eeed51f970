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
#include <memory>
#include <string>

#include "lrchain/model.hpp"
#include "lrchain/sim/model_lattice_abi.h"

namespace lrchain {

struct CompiledModelInfo {
  bool from_cache = false;        // the shared object existed already
  std::filesystem::path library;  // the cached shared object (empty for the GiNaC fallback)
  std::string fallback_reason;    // non-empty: no compiler, evaluated through GiNaC in double precision
};

// The model of `path` with compiled evaluators; when the compiler is not installed, with the derived
// expressions evaluated by GiNaC in double precision instead (info->fallback_reason says so).
// Throws InputError for a bad model file (a failing derivation check included; the file read by
// read_model_file_bytes) or an unsafe cache directory, and std::runtime_error when the compiler fails
// (InputError naming LRCHAIN_MODEL_CXX when that variable chose it). `stop` (e.g. a SIGINT flag) is
// polled between the derivation's steps and while the compiler runs (its whole process group is
// killed): then lrchain::Interrupted (SIGINT) is thrown and nothing is left in the cache.
std::shared_ptr<const ModelDefinition> compile_model_file(const std::filesystem::path& path,
                                                          CompiledModelInfo* info = nullptr,
                                                          const std::atomic<bool>* stop = nullptr);
// The same of a file the model loader read and hashed already (read_model_file): not read again.
std::shared_ptr<const ModelDefinition> compile_model_file(const ModelFileContent& content,
                                                          CompiledModelInfo* info = nullptr,
                                                          const std::atomic<bool>* stop = nullptr);

// The lattice kernels (sim/include/lrchain/sim/model_lattice_abi.h) of the model file `path`, emitted by
// the lattice code generator and compiled like the evaluators: same cache, key rules (file bytes,
// compiler, lrchain version) and compiler, loaded with dlopen; the pointer keeps the library loaded.
// Checks the table's abi_version and model name. Throws InputError for a bad model file or when the
// compiler is not installed (no slow fallback for lattice runs), std::runtime_error when it fails.
std::shared_ptr<const lrchain_lattice_kernels> compile_model_lattice(const std::filesystem::path& path,
                                                                     CompiledModelInfo* info = nullptr,
                                                                     const std::atomic<bool>* stop = nullptr);
// The same of a file the model loader read and hashed already (read_model_file): not read again.
std::shared_ptr<const lrchain_lattice_kernels> compile_model_lattice(const ModelFileContent& content,
                                                                     CompiledModelInfo* info = nullptr,
                                                                     const std::atomic<bool>* stop = nullptr);

// Throws the InputError of compile_model_lattice when the lattice code of `path` is not cached and
// the compiler is not installed: lattice runs call it before anything else.
void check_lattice_compiler(const std::filesystem::path& path);
void check_lattice_compiler(const ModelFileContent& content);

// Version of the emitted evaluator code (its functions and their outputs): part of the cache key,
// so a cached shared object of an older emitter is never loaded. "evaluators 4": harmonics() and the
// shared extended-precision prologue (model_evaluator_support.hpp).
inline constexpr const char* kEvaluatorCode = "evaluators 4";

// Kind of the cached lattice code: "lattice V" with V the kernel table's LRCHAIN_LATTICE_ABI_VERSION,
// so that a library of an older table is never loaded (the file is compiled again).
std::string lattice_code_kind();

// The cache key of a model file's bytes compiled by `compiler` (its path and version line) for
// lrchain `version` into `kind` of code (kEvaluatorCode, or lattice_code_kind()): the SHA-256 (64
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

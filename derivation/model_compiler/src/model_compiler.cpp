#include "lrchain/model_compiler.hpp"

#include <dlfcn.h>
#include <signal.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <mutex>
#include <stdexcept>
#include <vector>

#include "evaluator_support_text.hpp"
#include "ginac_evaluators.hpp"
#include "lrchain/derivation/c_string_literal.hpp"
#include "lrchain/derivation/derivation_stop.hpp"
#include "lrchain/derivation/lattice_codegen.hpp"
#include "lrchain/derivation/model_emission.hpp"
#include "lrchain/derivation/symbolic_lock.hpp"
#include "lrchain/errors.hpp"
#include "lrchain/process.hpp"
#include "lrchain/provenance.hpp"
#include "lrchain/sha256.hpp"
#include "model_cache.hpp"
#include "model_metadata.hpp"

namespace fs = std::filesystem;

namespace lrchain {

namespace {

// The last dlerror(), or a sentence when there is none.
std::string dlerror_text() {
  const char* e = dlerror();
  return e ? e : "no error reported";
}

// A symbol of the model-file SHA-256 both kinds of object carry: checked after loading, so an entry
// holding another file's object (copied over, say) is a miss, never another model's numbers.
constexpr const char* kFileShaSymbol = "lrchain_model_file_sha256";
// The object's LRCHAIN_COMPILED_MODEL_ABI_VERSION (lrchain/compiled_model_abi.h).
constexpr const char* kAbiVersionSymbol = "lrchain_compiled_model_abi_version";

std::string file_sha256_definition(const std::string& file_sha256) {
  return "\nextern \"C\" const char " + std::string(kFileShaSymbol) + "[] = " + derivation::c_string_literal(file_sha256) + ";\n";
}

// The evaluators as self-contained translation units of the shared object: the first holds the
// parameters' intermediates and the dispersion with the model's description and identity, the
// others nls and harmonics (the large functions), each with the small functions both call (inline).
// Nothing of the model file reaches them as text but identifiers and parsed expressions; its
// description (JSON) and hash only as C string literals (derivation::c_string_literal).
std::vector<std::string> evaluator_sources(const derivation::ModelDerivation& m, const derivation::Symbols& s) {
  const derivation::EvaluatorParts parts = derivation::model_evaluator_parts(m, s);
  const auto unit = [&](const std::string& functions, const std::string& tail) {
    return std::string("// lrchain model evaluators, compiled at run time by lrchain. Do not edit.\n#include <cmath>\n") +
           model_compiler_detail::evaluator_support_text + "\nnamespace lrchain_model {\n\n" + parts.common + functions +
           "\n}  // namespace lrchain_model\n\n" + tail;
  };
  return {
      unit("", "extern \"C\" const char lrchain_model_metadata[] = " + derivation::c_string_literal(model_metadata_json(m)) +
                   ";\n" + file_sha256_definition(m.file.sha256) + "extern \"C\" const int " + kAbiVersionSymbol + " = " +
                   std::to_string(LRCHAIN_COMPILED_MODEL_ABI_VERSION) +
                   ";\n\nextern \"C\" {\n"
                   "void lrchain_model_intermediates(const double* p, double* q) { lrchain_model::intermediates(p, q); }\n"
                   "void lrchain_model_dispersion(double D1, double sigma, const double* q, double* w) { lrchain_model::dispersion(D1, sigma, q, w); }\n"
                   "}\n"),
      unit(parts.nls, "extern \"C\" void lrchain_model_nls(double D1, double sigma, double omega, const double* q, double* out) "
                      "{ lrchain_model::nls(D1, sigma, omega, q, out); }\n"),
      unit(parts.harmonics, "extern \"C\" void lrchain_model_harmonics(double D1, double sigma, double omega, const double* q, "
                            "double* out) { lrchain_model::harmonics(D1, sigma, omega, q, out); }\n")};
}

// "12.3 s" (progress lines).
std::string seconds_text(double seconds) {
  char text[32];
  std::snprintf(text, sizeof text, "%.1f s", seconds);
  return text;
}

// The first line of `compiler --version` (part of the cache key), once per compiler and process.
std::string compiler_version(const std::string& compiler) {
  static std::map<std::string, std::string> known;
  static std::mutex mutex;
  const std::lock_guard<std::mutex> lock(mutex);
  const auto it = known.find(compiler);
  if (it != known.end()) return it->second;
  std::string version;
  if (program_in_path(compiler)) {
    ProcessOptions options;
    options.capture_stdout = true;
    const ProcessResult r = run_program({compiler, "--version"}, options);
    if (r.ok()) version = r.output.substr(0, r.output.find('\n'));
  }
  return known[compiler] = version;
}

// The one cache entry of a model file's bytes (its evaluators and lattice kernels in one object).
// The key holds the build's git commit beside the version: a change of the code generator that
// leaves the ABI alone must not serve objects the older generator emitted.
CacheEntry cache_entry(const std::string& bytes) {
  const std::string compiler = model_compiler_path();
  static const std::string build = std::string(LRCHAIN_VERSION) + " " + build_info().commit;
  return {model_cache_directory(),
          "model-" + model_cache_key(bytes, compiler + "\n" + compiler_version(compiler), build, compiled_model_code_kind())};
}

// `make()` (emitting code with GiNaC) with a failure of the symbolic engine reported as the file's
// input error, naming its first force.
template <class Make>
auto emitted(const derivation::ModelFile& file, const std::string& what, Make make) {
  try {
    return make();
  } catch (const InputError&) {
    throw;
  } catch (const derivation::DerivationStopped&) {
    throw;
  } catch (const std::bad_alloc&) {
    throw;
  } catch (const std::exception& e) {
    const std::string message = e.what();
    throw InputError((file.first_force_where.empty() ? file.path : file.first_force_where) + ": the " + what +
                     " of model " + file.name + " cannot be generated (" + message.substr(0, message.find('\n')) + ")");
  }
}

// compile_into_entry with a failing compiler reported as the user's input error when the user chose
// it (LRCHAIN_MODEL_CXX: exit 2 naming the variable), else as lrchain's (std::runtime_error: exit 1).
void compile_entry(const std::vector<CompileUnit>& units, const CacheEntry& entry, const std::string& what,
                   const std::atomic<bool>* stop) {
  try {
    compile_into_entry(units, model_compiler_path(), entry, what, stop);
  } catch (const CompilerFailed& e) {
    const char* chosen = std::getenv("LRCHAIN_MODEL_CXX");
    if (chosen && *chosen) throw InputError(std::string("LRCHAIN_MODEL_CXX: ") + e.what());
    throw;
  }
}

// `work()` with a stopped derivation reported as lrchain::Interrupted (SIGINT; a front end that
// knows the signal says which), nothing cached.
template <class Work>
auto stoppable(const std::string& what, const std::atomic<bool>* stop, Work work) {
  const derivation::DerivationStopScope scope(stop);
  try {
    return work();
  } catch (const derivation::DerivationStopped&) {
    throw Interrupted(SIGINT, "stopped while deriving " + what + "; nothing was cached");
  }
}

// The object's recorded model-file SHA-256 is the file's (else std::runtime_error).
void check_file_sha256(void* handle, const std::string& file_sha256, const fs::path& library) {
  const auto* recorded = static_cast<const char*>(dlsym(handle, kFileShaSymbol));
  if (!recorded || file_sha256 != recorded)
    throw std::runtime_error(library.string() + ": an object of another model file");
}

template <class Function>
Function symbol(void* handle, const char* name, const fs::path& library) {
  void* p = dlsym(handle, name);
  if (!p) throw std::runtime_error(library.string() + ": missing " + name);
  return reinterpret_cast<Function>(p);
}

// The lattice kernels of a loaded object (null when it has none), the table checked against the ABI version and the model's name.
std::shared_ptr<const lrchain_lattice_kernels> lattice_kernels(void* handle, const std::shared_ptr<void>& owner,
                                                               const fs::path& library, const std::string& name) {
  const auto entry = reinterpret_cast<const lrchain_lattice_kernels* (*)()>(dlsym(handle, ("lrchain_lattice_" + name).c_str()));
  if (!entry) return nullptr;  // a model whose force laws a lattice cannot run
  const lrchain_lattice_kernels* kernels = entry();
  if (!kernels || kernels->abi_version != LRCHAIN_COMPILED_MODEL_ABI_VERSION)
    throw std::runtime_error(library.string() + ": lattice kernels of ABI version " +
                             (kernels ? std::to_string(kernels->abi_version) : std::string("none")) + ", expected " +
                             std::to_string(LRCHAIN_COMPILED_MODEL_ABI_VERSION));
  if (name != kernels->model_name)
    throw std::runtime_error(library.string() + ": kernels of model " + kernels->model_name + ", expected " + name);
  return std::shared_ptr<const lrchain_lattice_kernels>(owner, kernels);  // keeps the library loaded
}

// A loaded model object (lrchain/compiled_model_abi.h) as a model definition and its lattice kernels
// (the handle lives as long as either); std::runtime_error when it is not this file's object.
CompiledModel load_library(void* handle, const fs::path& library, const std::string& file_sha256) {
  std::shared_ptr<void> owner(handle, [](void* h) { dlclose(h); });
  check_file_sha256(handle, file_sha256, library);
  const auto* version = static_cast<const int*>(dlsym(handle, kAbiVersionSymbol));
  if (!version || *version != LRCHAIN_COMPILED_MODEL_ABI_VERSION)
    throw std::runtime_error(library.string() + ": not an object of compiled-model ABI version " +
                             std::to_string(LRCHAIN_COMPILED_MODEL_ABI_VERSION));
  const auto* text = static_cast<const char*>(dlsym(handle, "lrchain_model_metadata"));
  if (!text) throw std::runtime_error(library.string() + ": no model description");
  auto d = std::make_shared<ModelDefinition>(parse_model_metadata(text, library.string()));
  d->evaluators.intermediates = symbol<lrchain_model_intermediates_function>(handle, "lrchain_model_intermediates", library);
  d->evaluators.dispersion = symbol<lrchain_model_dispersion_function>(handle, "lrchain_model_dispersion", library);
  d->evaluators.nls = symbol<lrchain_model_nls_function>(handle, "lrchain_model_nls", library);
  d->evaluators.harmonics = symbol<lrchain_model_harmonics_function>(handle, "lrchain_model_harmonics", library);
  if (d->file_sha256 != file_sha256) throw std::runtime_error(library.string() + ": an object of another model file");
  d->keep_alive = owner;
  CompiledModel compiled;
  compiled.kernels = lattice_kernels(handle, owner, library, d->name);
  compiled.definition = std::move(d);
  return compiled;
}

}  // namespace

std::string model_cache_key(const std::string& bytes, const std::string& compiler, const std::string& version,
                            const std::string& kind) {
  Sha256Builder key;
  key.field("lrchain model cache key 2").field(bytes).field(compiler).field(version).field(kind);
  return key.hex();
}

std::string model_compiler_version() { return LRCHAIN_VERSION; }

std::string compiled_model_code_kind() { return "compiled model " + std::to_string(LRCHAIN_COMPILED_MODEL_ABI_VERSION); }

std::string model_compiler_path() {
  const char* chosen = std::getenv("LRCHAIN_MODEL_CXX");
  return chosen && *chosen ? chosen : LRCHAIN_CXX_COMPILER;
}

bool model_compiler_available() { return program_in_path(model_compiler_path()); }

std::string model_fallback_warning(const std::string& model_name, const CompiledModelInfo& info) {
  return "model " + model_name + " is evaluated through GiNaC in double precision, far slower than compiled code, because " +
         info.fallback_reason + "; install it (Debian: apt install g++) to compile the model once into the cache";
}

// The work of compile_model inside its stop scope.
static CompiledModel compile_model_now(const ModelFileContent& content, CompiledModelInfo* info,
                                       const std::atomic<bool>* stop, const CompileProgress& progress);

CompiledModel compile_model(const ModelFileContent& content, CompiledModelInfo* info, const std::atomic<bool>* stop,
                            const CompileProgress& progress) {
  return stoppable("model file " + content.path, stop, [&] { return compile_model_now(content, info, stop, progress); });
}

std::shared_ptr<const ModelDefinition> compile_model_file(const fs::path& path, CompiledModelInfo* info,
                                                          const std::atomic<bool>* stop) {
  return compile_model(read_model_file(path.string()), info, stop).definition;
}

std::shared_ptr<const ModelDefinition> compile_model_file(const ModelFileContent& content, CompiledModelInfo* info,
                                                          const std::atomic<bool>* stop) {
  return compile_model(content, info, stop).definition;
}

static CompiledModel compile_model_now(const ModelFileContent& content, CompiledModelInfo* info,
                                       const std::atomic<bool>* stop, const CompileProgress& progress) {
  const std::string& bytes = content.bytes;
  const fs::path path(content.path);
  const std::lock_guard<std::recursive_mutex> lock(derivation::symbolic_engine_mutex());
  const std::string compiler = model_compiler_path();
  const std::string& file_sha256 = content.sha256;
  const CacheEntry entry = cache_entry(bytes);
  fs::path library;
  if (void* handle = open_verified_object(entry, &library)) {
    if (info) info->from_cache = true, info->library = library;
    try {
      return load_library(handle, library, file_sha256);
    } catch (const std::runtime_error&) {
      if (info) info->from_cache = false;  // not this file's object: compiled again below
    }
  }
  // Derive (a bad file or a failing check is the user's input error) before touching the cache.
  const derivation::Symbols symbols;
  derivation::ModelFile file = derivation::parse_model_text(bytes, path.string());
  const std::string shown = file.path;
  const auto say = [&](const std::string& step) {
    if (progress) progress(step);
  };
  say("deriving model " + file.name + " (once; later loads use the cache)");
  const auto values = derivation::parameter_values(file, {});
  const derivation::ModelFile lattice_file = file;
  const auto m = derivation::derive_model(std::move(file), values, symbols);
  if (!m->passed())
    throw InputError(shown + ": a derivation check failed for model " + m->file.name + " (see `lrchain derive --model " +
                     shown + "`)");
  if (!program_in_path(compiler)) {
    // No compiler: the derived expressions evaluated by GiNaC in double precision instead, no lattice kernels.
    CompiledModel fallback;
    auto d = std::make_shared<ModelDefinition>(parse_model_metadata(model_metadata_json(*m), "the derived model"));
    d->evaluators.object = std::make_shared<GinacModelEvaluators>(*m, symbols);
    fallback.definition = std::move(d);
    if (info) {
      info->library.clear();
      info->fallback_reason = "the C++ compiler " + compiler + " is not installed";
    }
    return fallback;
  }
  say(seconds_text(m->derive_seconds) + " deriving, " + seconds_text(m->check_seconds) +
      " checking at 50 digits; emitting its evaluators and lattice kernels");
  const auto emit_start = std::chrono::steady_clock::now();
  // Translation units compiled at once and linked into one object: the evaluators (-O2: three units,
  // nls and harmonics apart), and the lattice kernels (-O3 as the shipped kernels of a Release build; their attributes pick the vector width).
  std::vector<CompileUnit> units;
  for (std::string& source : emitted(m->file, "evaluators", [&] { return evaluator_sources(*m, symbols); }))
    units.push_back({std::move(source), {"-O2"}});
  try {
    units.push_back({emitted(m->file, "lattice code", [&] { return derivation::lattice_source(lattice_file); }), {"-O3", "-DNDEBUG"}});
  } catch (const InputError&) {
    // Force laws a lattice cannot run (compile_model_lattice says why): the evaluators alone.
  }
  std::size_t bytes_emitted = 0;
  for (const CompileUnit& u : units) bytes_emitted += u.source.size();
  say(seconds_text(std::chrono::duration<double>(std::chrono::steady_clock::now() - emit_start).count()) + " emitting " +
      std::to_string(bytes_emitted / 1024) + " KiB of C++; compiling " + std::to_string(units.size()) +
      " translation units at once with " + compiler);
  compile_entry(units, entry, "the model of " + shown, stop);
  void* handle = open_verified_object(entry, &library);
  if (info) info->from_cache = false, info->library = library;
  if (!handle) throw std::runtime_error("cannot load " + library.string() + " just compiled: " + dlerror_text());
  return load_library(handle, library, file_sha256);
}

void check_lattice_compiler(const fs::path& path) { check_lattice_compiler(read_model_file(path.string())); }

void check_lattice_compiler(const ModelFileContent& content) {
  const std::lock_guard<std::recursive_mutex> lock(derivation::symbolic_engine_mutex());
  if (has_verified_object(cache_entry(content.bytes))) return;
  const std::string compiler = model_compiler_path();
  if (!program_in_path(compiler))
    throw InputError("--model " + content.path + ": lattice runs of a model file compile its lattice code with the C++ "
                     "compiler " + compiler + ", which is not installed (evaluating the forces through GiNaC would be "
                     "far too slow for a lattice run); install it (Debian: apt install g++) or set LRCHAIN_MODEL_CXX");
}

std::shared_ptr<const lrchain_lattice_kernels> compile_model_lattice(const fs::path& path, CompiledModelInfo* info,
                                                                     const std::atomic<bool>* stop) {
  return compile_model_lattice(read_model_file(path.string()), info, stop);
}

std::shared_ptr<const lrchain_lattice_kernels> compile_model_lattice(const ModelFileContent& content, CompiledModelInfo* info,
                                                                     const std::atomic<bool>* stop) {
  check_lattice_compiler(content);
  auto kernels = compile_model(content, info, stop).kernels;
  if (kernels) return kernels;
  // Compiled without kernels: the lattice code generator's refusal (an InputError naming the force law),
  // derived again under the symbolic engine's lock (GiNaC is not thread-safe; Python releases the GIL here).
  {
    const std::lock_guard<std::recursive_mutex> lock(derivation::symbolic_engine_mutex());
    const derivation::ModelFile file = derivation::parse_model_text(content.bytes, content.path);
    emitted(file, "lattice code", [&] { return derivation::lattice_source(file); });
  }
  throw std::runtime_error(content.path + ": the compiled model has no lattice kernels; delete its entry in " +
                           model_cache_directory().string() + " to compile it again");
}

}  // namespace lrchain

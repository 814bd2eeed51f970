#include "lrchain/model_compiler.hpp"

#include <dlfcn.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <random>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "evaluator_support_text.hpp"
#include "ginac_evaluators.hpp"
#include "lrchain/derivation/lattice_codegen.hpp"
#include "lrchain/derivation/model_emission.hpp"
#include "lrchain/errors.hpp"
#include "lrchain/process.hpp"
#include "lrchain/sim/model_lattice_abi.h"

namespace fs = std::filesystem;

namespace lrchain {

namespace {

std::string read_bytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path.string() + ": cannot read the model file");
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// The cache key's kind of lattice code: a new kernel ABI compiles the model file again.

// $XDG_CACHE_HOME/lrchain, else $HOME/.cache/lrchain.
fs::path cache_directory() {
  const char* xdg = std::getenv("XDG_CACHE_HOME");
  if (xdg && *xdg && fs::path(xdg).is_absolute()) return fs::path(xdg) / "lrchain";
  const char* home = std::getenv("HOME");
  if (!home || !*home) throw std::runtime_error("cannot place the model cache: neither XDG_CACHE_HOME nor HOME is set");
  return fs::path(home) / ".cache" / "lrchain";
}

std::string number(double v) {
  char buffer[40];
  std::snprintf(buffer, sizeof buffer, "%.17g", v);
  return buffer;
}

// The model's description, one item per line (read back by parse_metadata).
std::string metadata(const derivation::ModelDerivation& m) {
  std::ostringstream out;
  out << "name " << m.file.name << "\ndescription " << m.file.description << "\nhash " << m.file.hash
      << "\nmean_flow " << m.coefficients.mean_flow << "\ndegree " << m.branches.size() << "\n";
  for (const auto& p : m.file.parameters) {
    const auto& r = p.range;
    out << "parameter " << p.name << " " << number(p.default_value.to_double()) << " " << r.has_lower << " "
        << (r.has_lower ? number(r.lower.to_double()) : "0") << " " << r.lower_closed << " " << r.has_upper << " "
        << (r.has_upper ? number(r.upper.to_double()) : "0") << " " << r.upper_closed << " " << r.text << "\n";
  }
  for (const auto& i : m.file.intermediates) out << "intermediate " << i.name << "\n";
  for (const auto& b : m.branches) out << "branch " << b.name << "\n";
  return out.str();
}

ModelDefinition parse_metadata(const std::string& text) {
  ModelDefinition d;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream fields(line);
    std::string key;
    fields >> key;
    std::string rest;
    std::getline(fields >> std::ws, rest);
    std::istringstream values(rest);
    if (key == "name") d.name = rest;
    else if (key == "description") d.description = rest;
    else if (key == "hash") values >> d.file_hash;
    else if (key == "mean_flow") values >> d.mean_flow;
    else if (key == "degree") values >> d.degree;
    else if (key == "intermediate") d.intermediates.push_back(rest);
    else if (key == "branch") d.branch_names.push_back(rest);
    else if (key == "parameter") {
      ModelParameter p;
      values >> p.name >> p.default_value >> p.has_lower >> p.lower >> p.lower_closed >> p.has_upper >> p.upper >> p.upper_closed;
      std::getline(values >> std::ws, p.range_text);
      d.parameters.push_back(p);
    }
  }
  return d;
}

// C++ string literal of `text`.
std::string literal(const std::string& text) {
  std::string out = "\"";
  for (char c : text) {
    if (c == '\n') out += "\\n\"\n\"";
    else if (c == '"' || c == '\\') out += std::string("\\") + c;
    else out += c;
  }
  return out + "\"";
}

// Self-contained source of the shared object: the evaluators and C entry points.
std::string shared_object_source(const derivation::ModelDerivation& m, const derivation::Symbols& s) {
  return "// lrchain model " + m.file.name + ", emitted from " + m.file.path + "\n#include <cmath>\n" +
         model_compiler_detail::evaluator_support_text + "\nnamespace lrchain_model {\n\n" +
         derivation::model_evaluator_functions(m, s) +
         "\n}  // namespace lrchain_model\n\n"
         "extern \"C\" const char lrchain_model_metadata[] = " + literal(metadata(m)) + ";\n\n"
         "extern \"C\" {\n"
         "void lrchain_model_intermediates(const double* p, double* q) { lrchain_model::intermediates(p, q); }\n"
         "void lrchain_model_dispersion(double D1, double sigma, const double* q, double* w) { lrchain_model::dispersion(D1, sigma, q, w); }\n"
         "void lrchain_model_nls(double D1, double sigma, double omega, const double* q, double* out) { lrchain_model::nls(D1, sigma, omega, q, out); }\n"
         "void lrchain_model_harmonics(double D1, double sigma, double omega, const double* q, double* out) { lrchain_model::harmonics(D1, sigma, omega, q, out); }\n"
         "}\n";
}

// Compiles `source` into the shared object `library` in `directory`: written and compiled under a
// unique temporary name, then renamed into place, so concurrent processes never see a partial file.
void compile_into_cache(const std::string& source_text, const std::vector<std::string>& optimisation,
                        const fs::path& directory, const fs::path& library, const std::string& what) {
  std::error_code ec;
  fs::create_directories(directory, ec);
  if (ec) throw std::runtime_error("cannot create the model cache " + directory.string() + ": " + ec.message());
  std::random_device random;
  const std::string stem = ".model-" + std::to_string(::getpid()) + "-" + std::to_string(random());
  const fs::path source = directory / (stem + ".cpp"), object = directory / (stem + ".so");
  {
    std::ofstream out(source, std::ios::binary);
    out << source_text;
    if (!out) throw std::runtime_error("cannot write " + source.string());
  }
  ProcessOptions options;
  options.capture_stderr = true;
  std::vector<std::string> argv{model_compiler_path(), "-std=c++17"};
  argv.insert(argv.end(), optimisation.begin(), optimisation.end());
  argv.insert(argv.end(), {"-fPIC", "-shared", "-o", object.string(), source.string()});
  const ProcessResult r = run_program(argv, options);
  fs::remove(source, ec);
  if (!r.ok()) {
    fs::remove(object, ec);
    throw std::runtime_error("compiling " + what + " failed: " + r.error_output.substr(0, r.error_output.find('\n')));
  }
  fs::rename(object, library, ec);
  if (ec) {
    fs::remove(object, ec);
    throw std::runtime_error("cannot place " + library.string() + " in the model cache");
  }
}

// The cache entry of a model file's bytes for one kind of code (kEvaluatorCode, lattice_code_kind()).
fs::path cache_entry(const std::string& bytes, const std::string& kind, const std::string& prefix) {
  return cache_directory() / (prefix + model_hash_text(model_cache_key(bytes, model_compiler_path(), LRCHAIN_VERSION, kind)).substr(2) + ".so");
}

template <class Function>
Function symbol(void* handle, const char* name, const fs::path& library) {
  void* p = dlsym(handle, name);
  if (!p) throw std::runtime_error(library.string() + ": missing " + name);
  return reinterpret_cast<Function>(p);
}

// Loads a cached shared object as a model definition (the handle lives as long as the definition).
std::shared_ptr<const ModelDefinition> load_library(const fs::path& library) {
  void* handle = dlopen(library.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!handle) throw std::runtime_error("cannot load " + library.string() + ": " + dlerror());
  std::shared_ptr<void> owner(handle, [](void* h) { dlclose(h); });
  const auto* text = static_cast<const char*>(dlsym(handle, "lrchain_model_metadata"));
  if (!text) throw std::runtime_error(library.string() + ": no model description");
  auto d = std::make_shared<ModelDefinition>(parse_metadata(text));
  d->evaluators.intermediates = symbol<void (*)(const double*, double*)>(handle, "lrchain_model_intermediates", library);
  d->evaluators.dispersion = symbol<void (*)(double, double, const double*, double*)>(handle, "lrchain_model_dispersion", library);
  d->evaluators.nls = symbol<void (*)(double, double, double, const double*, double*)>(handle, "lrchain_model_nls", library);
  d->evaluators.harmonics = symbol<void (*)(double, double, double, const double*, double*)>(handle, "lrchain_model_harmonics", library);
  if (d->name.empty() || d->branch_names.empty()) throw std::runtime_error(library.string() + ": no model description");
  d->keep_alive = owner;
  return d;
}

// Loads a cached lattice library and checks its kernel table against the model file's name.
std::shared_ptr<const lrchain_lattice_kernels> load_lattice_library(const fs::path& library, const std::string& name) {
  void* handle = dlopen(library.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!handle) throw std::runtime_error("cannot load " + library.string() + ": " + dlerror());
  std::shared_ptr<void> owner(handle, [](void* h) { dlclose(h); });
  const auto entry = symbol<const lrchain_lattice_kernels* (*)()>(handle, ("lrchain_lattice_" + name).c_str(), library);
  const lrchain_lattice_kernels* kernels = entry();
  if (!kernels || kernels->abi_version != LRCHAIN_LATTICE_ABI_VERSION)
    throw std::runtime_error(library.string() + ": lattice kernels of ABI version " +
                             (kernels ? std::to_string(kernels->abi_version) : std::string("none")) + ", expected " +
                             std::to_string(LRCHAIN_LATTICE_ABI_VERSION) + " (delete the file to recompile it)");
  if (name != kernels->model_name)
    throw std::runtime_error(library.string() + ": kernels of model " + kernels->model_name + ", expected " + name);
  return std::shared_ptr<const lrchain_lattice_kernels>(owner, kernels);  // keeps the library loaded
}

}  // namespace

std::uint64_t model_cache_key(const std::string& bytes, const std::string& compiler, const std::string& version,
                              const std::string& kind) {
  return fnv1a_64(compiler + "\n" + version + "\n" + kind + "\n", fnv1a_64(bytes));
}

std::string model_compiler_version() { return LRCHAIN_VERSION; }

std::string lattice_code_kind() { return "lattice " + std::to_string(LRCHAIN_LATTICE_ABI_VERSION); }

std::string model_compiler_path() {
  const char* chosen = std::getenv("LRCHAIN_MODEL_CXX");
  return chosen && *chosen ? chosen : LRCHAIN_CXX_COMPILER;
}

bool model_compiler_available() { return program_in_path(model_compiler_path()); }

std::shared_ptr<const ModelDefinition> compile_model_file(const fs::path& path, CompiledModelInfo* info) {
  const std::string bytes = read_bytes(path);
  const std::string compiler = model_compiler_path();
  const fs::path library = cache_entry(bytes, kEvaluatorCode, "model-");
  const fs::path directory = library.parent_path();
  if (info) info->library = library;
  std::error_code ec;
  if (fs::exists(library, ec)) {
    if (info) info->from_cache = true;
    return load_library(library);
  }
  // Derive (a bad file or a failing check is the user's input error) before touching the cache.
  const derivation::Symbols symbols;
  derivation::ModelFile file = derivation::parse_model_text(bytes, path.string());
  const auto values = derivation::parameter_values(file, {});
  const auto m = derivation::derive_model(std::move(file), values, symbols);
  if (!m->passed())
    throw InputError(path.string() + ": a derivation check failed for model " + m->file.name +
                     " (see `lrchain derive --model " + path.string() + "`)");
  if (!program_in_path(compiler)) {
    // No compiler: the derived expressions evaluated by GiNaC in double precision instead.
    auto d = std::make_shared<ModelDefinition>(parse_metadata(metadata(*m)));
    d->evaluators.object = std::make_shared<GinacModelEvaluators>(*m, symbols);
    if (info) {
      info->library.clear();
      info->fallback_reason = "the C++ compiler " + compiler + " is not installed";
    }
    return d;
  }
  compile_into_cache(shared_object_source(*m, symbols), {"-O2"}, directory, library, "the evaluators of " + path.string());
  return load_library(library);
}

void check_lattice_compiler(const fs::path& path) {
  if (fs::exists(cache_entry(read_bytes(path), lattice_code_kind(), "lattice-"))) return;
  const std::string compiler = model_compiler_path();
  if (!program_in_path(compiler))
    throw InputError("--model " + path.string() + ": lattice runs of a model file compile its lattice code with the C++ "
                     "compiler " + compiler + ", which is not installed (evaluating the forces through GiNaC would be "
                     "far too slow for a lattice run); install it (Debian: apt install g++) or set LRCHAIN_MODEL_CXX");
}

std::shared_ptr<const lrchain_lattice_kernels> compile_model_lattice(const fs::path& path, CompiledModelInfo* info) {
  const std::string bytes = read_bytes(path);
  // The model's name first (a bad file is the user's input error, reported before the cache is touched).
  const derivation::ModelFile file = derivation::parse_model_text(bytes, path.string());
  const fs::path library = cache_entry(bytes, lattice_code_kind(), "lattice-");
  if (info) info->library = library;
  std::error_code ec;
  if (fs::exists(library, ec)) {
    if (info) info->from_cache = true;
    return load_lattice_library(library, file.name);
  }
  check_lattice_compiler(path);
  // -O3 as the shipped kernels (Release build); the kernels' own attributes pick the vector width.
  compile_into_cache(derivation::lattice_source(file), {"-O3", "-DNDEBUG"}, library.parent_path(), library,
                     "the lattice code of " + path.string());
  return load_lattice_library(library, file.name);
}

}  // namespace lrchain

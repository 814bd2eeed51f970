#include "model_option.hpp"

#include <chrono>
#include <csignal>
#include <iostream>

#include "lrchain/errors.hpp"
#include "lrchain/numeric_parse.hpp"
#include "lrchain/sim/model_lattice_bloch.hpp"
#include "shipped_data.hpp"
#include "stop_signals.hpp"
#ifdef LRCHAIN_WITH_MODEL_COMPILER
#include "lrchain/model_compiler.hpp"
#endif

namespace lrchain::cli {

namespace {

constexpr const char* kAliases[] = {"--alpha", "--delta0", "--kappa", "--rho"};

std::vector<std::pair<std::string, double>> set_values(const std::vector<std::string>& set) {
  std::vector<std::pair<std::string, double>> values;
  for (const auto& s : set) {
    const auto eq = s.find('=');
    if (eq == std::string::npos || eq == 0) throw InputError("--set " + s + ": expected NAME=VALUE, e.g. --set rho=1/3");
    const std::string name = s.substr(0, eq);
    values.emplace_back(name, parse_number(s.substr(eq + 1), name));
  }
  return values;
}

// `compile()` (deriving and compiling a model file) stopped by SIGINT/SIGTERM: the compiler's
// process group killed, nothing cached, exit 130/143 with one line naming the signal.
template <class Compile>
auto until_stopped(Compile compile) {
  const StopSignals signals;
  try {
    return compile();
  } catch (const Interrupted& e) {
    const int signal_number = StopSignals::received() != 0 ? StopSignals::received() : SIGINT;
    const std::string what = e.what();
    throw Interrupted(signal_number, "interrupted by " + std::string(StopSignals::name(signal_number)) + ": " + what);
  }
}

}  // namespace

void add_model_file_options(CLI::App& cmd, ModelSelection& selection) {
  cmd.add_option_function<std::string>(
         "--model", [&selection](const std::string& text) { selection.file = resolve_model_argument(text); },
         "lattice model: a model file (docs/models.md), or the name of a shipped model, e.g. klein_gordon or "
         "fput (default: the resonant chain)")
      ->type_name("FILE");
  cmd.add_option("--set", selection.set, "model parameter, repeatable: --set w0=2 --set b=1/3 (default: the model file's defaults)")->type_name("NAME=VALUE");
}

Model load_selected_model(const ModelSelection& selection, const CLI::App& cmd, const Params& aliases, bool lattice_run) {
  std::vector<std::pair<std::string, double>> values;
  std::shared_ptr<const ModelDefinition> definition;
  // Shipped definitions live for the whole program: shared without owning.
  const auto shipped = [](const ModelDefinition* d) { return std::shared_ptr<const ModelDefinition>(std::shared_ptr<const ModelDefinition>(), d); };
  if (selection.file.empty()) {
    definition = shipped(find_shipped_model("resonant_chain"));
  } else {
    std::string bytes;
    try {
      bytes = read_model_file_bytes(selection.file);
    } catch (const InputError& e) {
      throw InputError(std::string("--model ") + e.what());
    }
    if (const ModelDefinition* m = find_shipped_model_by_bytes(bytes)) definition = shipped(m);
#ifdef LRCHAIN_WITH_MODEL_COMPILER
    if (!definition) {
      if (lattice_run) check_lattice_compiler(selection.file);
      CompiledModelInfo info;
      definition = until_stopped([&] { return compile_model_file(selection.file, &info, StopSignals::flag()); });
      if (!info.fallback_reason.empty()) std::cerr << "lrchain: warning: " << model_fallback_warning(definition->name, info) << "\n";
    }
#else
    if (!definition)
      throw InputError("--model " + selection.file +
                       ": not a shipped model file, and this build has no model compiler (configure with "
                       "LRCHAIN_BUILD_DERIVATION=ON)");
#endif
  }
  for (const char* alias : kAliases) {
    const CLI::Option* option = cmd.get_option_no_throw(alias);
    if (!option || option->count() == 0) continue;
    if (definition->name != "resonant_chain")
      throw InputError(std::string(alias) + " belongs to the resonant chain; model " + definition->name +
                       " takes --set NAME=VALUE");
    const std::string name = std::string(alias).substr(2);
    const double v = name == "alpha" ? aliases.alpha : name == "delta0" ? aliases.delta0 : name == "kappa" ? aliases.kappa : aliases.rho;
    values.emplace_back(name, v);
  }
  for (const auto& v : set_values(selection.set)) values.push_back(v);
  return Model(definition, values);
}

LatticeCode lattice_kernels_for(const ModelSelection& selection, const Model& model) {
  const auto start = std::chrono::steady_clock::now();
  LatticeCode code;
  if (const lrchain_lattice_kernels* shipped = sim::compiled_in_lattice_kernels(model)) {
    code.kernels = std::shared_ptr<const lrchain_lattice_kernels>(std::shared_ptr<const lrchain_lattice_kernels>(), shipped);
  } else {
#ifdef LRCHAIN_WITH_MODEL_COMPILER
    CompiledModelInfo info;
    code.kernels = until_stopped([&] { return compile_model_lattice(selection.file, &info, StopSignals::flag()); });
    code.compiled_in = false;
    code.from_cache = info.from_cache;
    code.library = info.library.string();
#else
    throw InputError("--model " + selection.file +
                     ": not a shipped model file, and this build has no model compiler for its lattice code (configure "
                     "with LRCHAIN_BUILD_DERIVATION=ON)");
#endif
  }
  if (std::size_t(code.kernels->parameter_count) != model.definition().parameters.size())
    throw std::runtime_error("the lattice code of model " + model.name() + " takes " +
                             std::to_string(code.kernels->parameter_count) + " parameters, its evaluators " +
                             std::to_string(model.definition().parameters.size()));
  code.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return code;
}

nlohmann::json lattice_code_json(const LatticeCode& code) {
  nlohmann::json j{{"compiled_in", code.compiled_in}, {"seconds", code.seconds}};
  j["from_cache"] = code.compiled_in ? nlohmann::json(nullptr) : nlohmann::json(code.from_cache);
  j["library"] = code.compiled_in ? nlohmann::json(nullptr) : nlohmann::json(code.library);
  return j;
}

}  // namespace lrchain::cli

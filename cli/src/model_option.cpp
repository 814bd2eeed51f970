#include "model_option.hpp"

#include <unistd.h>

#include <chrono>
#include <csignal>
#include <iostream>

#include <fmt/format.h>

#include "lrchain/errors.hpp"
#include "lrchain/numeric_parse.hpp"
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

#ifdef LRCHAIN_WITH_MODEL_COMPILER
// The run-time model compiler as the model loader calls it: SIGINT/SIGTERM stop a compile
// (until_stopped), the GiNaC fallback is a warning on stderr.
class CliModelCompiler final : public jobs::ModelCompiler {
 public:
  jobs::CompiledCode compile(const ModelFileContent& file) const override {
    CompiledModelInfo info;
    // Progress on stderr while a new file compiles, for a person at a terminal (not in pipes or tests).
    const bool terminal = ::isatty(STDERR_FILENO) != 0;
    const auto start = std::chrono::steady_clock::now();
    const CompileProgress progress = [&](const std::string& step) {
      if (terminal) std::cerr << "lrchain: model file " << file.path << ": " << step << " ..." << std::endl;
    };
    CompiledModel compiled = until_stopped([&] { return compile_model(file, &info, StopSignals::flag(), progress); });
    if (terminal && !info.from_cache && info.fallback_reason.empty())
      std::cerr << "lrchain: model file " << file.path << ": compiled in "
                << fmt::format("{:.1f}", std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count())
                << " s" << std::endl;
    if (!info.fallback_reason.empty())
      std::cerr << "lrchain: warning: " << model_fallback_warning(compiled.definition->name, info) << "\n";
    return {compiled.definition, compiled.kernels, info.from_cache, info.library.string()};
  }
  void refuse_lattice(const ModelFileContent& file) const override {
    until_stopped([&] { return compile_model_lattice(file, nullptr, StopSignals::flag()); });
  }
  void check_lattice(const ModelFileContent& file) const override { check_lattice_compiler(file); }
};
#endif

}  // namespace

std::shared_ptr<const jobs::ModelCompiler> model_compiler() {
#ifdef LRCHAIN_WITH_MODEL_COMPILER
  return std::make_shared<const CliModelCompiler>();
#else
  return nullptr;
#endif
}

void add_model_file_options(CLI::App& cmd, ModelSelection& selection) {
  cmd.add_option_function<std::string>(
         "--model", [&selection](const std::string& text) { selection.file = resolve_model_argument(text); },
         "lattice model: a model file (docs/models.md), or the name of a shipped model, e.g. klein_gordon or "
         "fput (default: the resonant chain)")
      ->type_name("FILE");
  cmd.add_option("--set", selection.set, "model parameter, repeatable: --set w0=2 --set b=1/3 (default: the model file's defaults)")->type_name("NAME=VALUE");
}

Model load_selected_model(const ModelSelection& selection, const CLI::App& cmd, const Params& aliases, bool lattice_run) {
  selection.source = std::make_shared<const jobs::ModelSource>(
      selection.file.empty() ? jobs::ModelSource::shipped("resonant_chain", "--model")
                             : jobs::ModelSource(selection.file, "--model", model_compiler(), lattice_run));
  const ModelDefinition& definition = *selection.source->definition();
  std::vector<std::pair<std::string, double>> values;
  for (const char* alias : kAliases) {
    const CLI::Option* option = cmd.get_option_no_throw(alias);
    if (!option || option->count() == 0) continue;
    if (definition.name != "resonant_chain")
      throw InputError(std::string(alias) + " belongs to the resonant chain; model " + definition.name +
                       " takes --set NAME=VALUE");
    const std::string name = std::string(alias).substr(2);
    const double v = name == "alpha" ? aliases.alpha : name == "delta0" ? aliases.delta0 : name == "kappa" ? aliases.kappa : aliases.rho;
    values.emplace_back(name, v);
  }
  for (const auto& v : set_values(selection.set)) values.push_back(v);
  return selection.source->model(values);
}

LatticeCode lattice_kernels_for(const ModelSelection& selection, const Model& model) {
  if (!selection.source || selection.source->definition().get() != &model.definition())
    throw std::logic_error("lattice_kernels_for: model " + model.name() + " was not loaded by load_selected_model");
  return selection.source->lattice();
}

}  // namespace lrchain::cli

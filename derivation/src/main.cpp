// lrchain-derive: performs the multiple-scale derivation, prints the report with its checks and
// writes lib/include/lrchain/generated/nls_coefficients.hpp and, with --models, one evaluator
// header per model file plus shipped_models.hpp (each through a temp file + rename).
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>
#include <utility>
#include <vector>

#include <unistd.h>

#include "lrchain/derivation/generate.hpp"
#include "lrchain/derivation/model_emission.hpp"
#include "lrchain/errors.hpp"

namespace fs = std::filesystem;

namespace {

// Exit codes of every lrchain program (lib/include/lrchain/exit_codes.hpp, which this target does
// not link): 1 runtime failure or failed checks, 2 bad input (nothing written).
constexpr int exit_runtime_error = 1;
constexpr int exit_invalid_input = 2;

// Why `dir` cannot be the output directory (empty if it can): it, or the nearest existing parent
// it would be created in, must be a writable directory.
std::string output_directory_problem(const std::string& dir) {
  std::error_code ec;
  fs::path p(dir);
  if (fs::exists(p, ec)) {
    if (!fs::is_directory(p, ec)) return "--out '" + dir + "' exists and is not a directory";
    if (::access(p.c_str(), W_OK | X_OK) != 0) return "--out '" + dir + "' is not writable";
    return {};
  }
  fs::path parent = fs::absolute(p, ec).parent_path();
  while (!parent.empty() && !fs::exists(parent, ec) && parent != parent.parent_path()) parent = parent.parent_path();
  if (!fs::is_directory(parent, ec))
    return "--out '" + dir + "' cannot be created: '" + parent.string() + "' is not a directory";
  if (::access(parent.c_str(), W_OK | X_OK) != 0)
    return "--out '" + dir + "' cannot be created: '" + parent.string() + "' is not writable";
  return {};
}

// Writes `text` to `target` through a temporary name and a rename.
bool write_file(const fs::path& target, const std::string& text) {
  const fs::path tmp = target.parent_path() / ("." + target.filename().string() + ".tmp");
  std::error_code ec;
  {
    std::ofstream f(tmp, std::ios::binary);
    f << text;
    if (!f) return false;
  }
  fs::rename(tmp, target, ec);
  if (ec) fs::remove(tmp, ec);
  return !ec;
}

// Derives every *.toml model in `dir` at its default parameters and adds its evaluator header
// and the list header to `files`; false when a model's checks fail.
// Models named in `double_models` get evaluators in double arithmetic (faster; omega'' by implicit
// differentiation, small theta in long double).
bool derive_model_files(const std::string& dir, const std::vector<std::string>& double_models,
                        std::vector<std::pair<std::string, std::string>>& files, bool quiet) {
  std::vector<fs::path> paths;
  for (const auto& entry : fs::directory_iterator(dir))
    if (entry.path().extension() == ".toml") paths.push_back(entry.path());
  std::sort(paths.begin(), paths.end());
  const lrchain::derivation::Symbols symbols;
  std::vector<std::string> names;
  bool passed = true;
  for (const auto& path : paths) {
    auto file = lrchain::derivation::load_model_file(path);
    const auto values = lrchain::derivation::parameter_values(file, {});
    const auto m = lrchain::derivation::derive_model(std::move(file), values, symbols);
    if (!quiet || !m->passed())
      std::cout << "model " << m->file.name << ": " << (m->passed() ? "checks passed" : "A CHECK FAILED") << " (derivation "
                << m->derive_seconds << " s, checks " << m->check_seconds << " s)\n";
    passed &= m->passed();
    names.push_back(m->file.name);
    const bool in_double = std::find(double_models.begin(), double_models.end(), m->file.name) != double_models.end();
    files.emplace_back("model_" + m->file.name + ".hpp",
                       lrchain::derivation::model_header(*m, symbols, in_double ? "double" : ""));
  }
  std::sort(names.begin(), names.end());
  files.emplace_back("shipped_models.hpp", lrchain::derivation::shipped_models_header(names));
  return passed;
}

}  // namespace

int main(int argc, char** argv) {
  std::string out_dir, models_dir;
  std::vector<std::string> double_models;
  bool quiet = false;
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--out") && i + 1 < argc) out_dir = argv[++i];
    else if (!std::strcmp(argv[i], "--models") && i + 1 < argc) models_dir = argv[++i];
    else if (!std::strcmp(argv[i], "--quiet")) quiet = true;
    else if (!std::strcmp(argv[i], "--double-evaluators") && i + 1 < argc) {
      std::string list = argv[++i];
      for (std::size_t start = 0, comma; start <= list.size(); start = comma + 1) {
        comma = std::min(list.find(',', start), list.size());
        if (comma > start) double_models.push_back(list.substr(start, comma - start));
      }
    }
    else {
      std::cerr << "usage: lrchain-derive [--out DIR] [--models MODELS_DIR] [--double-evaluators NAME,...] [--quiet]\n"
                   "  Derives the NLS coefficients of the resonant and homogeneous chains, checks them\n"
                   "  against the paper, and writes DIR/nls_coefficients.hpp (default: print report only).\n"
                   "  With --models, also derives every MODELS_DIR/*.toml (checks must pass) and writes\n"
                   "  DIR/model_<name>.hpp and DIR/shipped_models.hpp. A model's NLS evaluator computes in\n"
                   "  long double or __float128 (chosen by the cancellation measured in its expressions),\n"
                   "  or in double for the models named in --double-evaluators (faster: omega'' by implicit\n"
                   "  differentiation of det M; theta < 0.05 and sums that cancel go to a long double version).\n"
                   "  Exit codes: 0 all checks passed, 1 a check failed or a file could not be written,\n"
                   "  2 bad arguments or --out (nothing written).\n";
      return exit_invalid_input;
    }
  }
  if (!out_dir.empty()) {
    const std::string problem = output_directory_problem(out_dir);
    if (!problem.empty()) {
      std::cerr << "lrchain-derive: " << problem << "\n";
      return exit_invalid_input;
    }
  }
  const auto t0 = std::chrono::steady_clock::now();
  const auto d = lrchain::derivation::derive_all();
  const auto checks = lrchain::derivation::run_paper_checks(d.resonant_coefficients, d.homogeneous_coefficients, d.symbols);
  const std::string header = lrchain::derivation::generated_header(d);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (!quiet) std::cout << lrchain::derivation::report(d, checks);
  bool all_passed = true;
  for (const auto& c : checks) all_passed &= c.passed;
  std::vector<std::pair<std::string, std::string>> files{{"nls_coefficients.hpp", header}};
  if (!models_dir.empty()) {
    try {
      all_passed &= derive_model_files(models_dir, double_models, files, quiet);
    } catch (const lrchain::InputError& e) {
      std::cerr << "lrchain-derive: " << e.what() << "\n";
      return exit_invalid_input;
    }
  }
  if (!out_dir.empty()) {
    std::error_code ec;
    fs::create_directories(out_dir, ec);
    for (const auto& [name, text] : files) {
      if (!write_file(fs::path(out_dir) / name, text)) {
        std::cerr << "lrchain-derive: cannot write " << (fs::path(out_dir) / name).string() << "\n";
        return exit_runtime_error;
      }
      if (!quiet) std::cout << "wrote " << (fs::path(out_dir) / name).string() << "\n";
    }
  }
  if (!quiet) std::printf("derivation + checks + emission: %.2f s\n", seconds);
  return all_passed ? 0 : exit_runtime_error;
}

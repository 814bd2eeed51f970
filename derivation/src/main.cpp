// lrchain-derive: performs the multiple-scale derivation, prints the report with its checks and
// writes lib/include/lrchain/generated/nls_coefficients.hpp (temp file + rename).
#include <chrono>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>

#include <sys/personality.h>
#include <unistd.h>

#include "lrchain/derivation/generate.hpp"

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

}  // namespace

int main(int argc, char** argv) {
  // GiNaC orders the terms of sums and products by hash values that include the addresses of its
  // classes' type information, which address-space randomisation changes from run to run. The
  // emitted text must be byte-for-byte reproducible (no-drift test), so re-execute once with
  // randomisation disabled for this process.
  const int persona = personality(0xffffffff);
  if (persona != -1 && !(persona & ADDR_NO_RANDOMIZE) && personality(persona | ADDR_NO_RANDOMIZE) != -1)
    execv("/proc/self/exe", argv);  // returns only on failure; then continue as we are
  std::string out_dir;
  bool quiet = false;
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--out") && i + 1 < argc) out_dir = argv[++i];
    else if (!std::strcmp(argv[i], "--quiet")) quiet = true;
    else {
      std::cerr << "usage: lrchain-derive [--out DIR] [--quiet]\n"
                   "  Derives the NLS coefficients of the resonant and homogeneous chains, checks them\n"
                   "  against the paper, and writes DIR/nls_coefficients.hpp (default: print report only).\n"
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
  if (!out_dir.empty()) {
    const fs::path target = fs::path(out_dir) / "nls_coefficients.hpp";
    const fs::path tmp = fs::path(out_dir) / ".nls_coefficients.hpp.tmp";
    std::error_code ec;
    fs::create_directories(out_dir, ec);
    {
      std::ofstream f(tmp, std::ios::binary);
      f << header;
      if (ec || !f) {
        std::cerr << "lrchain-derive: cannot write " << tmp.string() << "\n";
        return exit_runtime_error;
      }
    }
    fs::rename(tmp, target, ec);
    if (ec) {
      fs::remove(tmp, ec);
      std::cerr << "lrchain-derive: cannot write " << target.string() << "\n";
      return exit_runtime_error;
    }
    if (!quiet) std::cout << "wrote " << target.string() << "\n";
  }
  if (!quiet) std::printf("derivation + checks + emission: %.2f s\n", seconds);
  return all_passed ? 0 : exit_runtime_error;
}

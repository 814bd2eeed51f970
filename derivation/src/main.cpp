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
                   "  against the paper, and writes DIR/nls_coefficients.hpp (default: print report only).\n";
      return 2;
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
    fs::create_directories(out_dir);
    {
      std::ofstream f(tmp, std::ios::binary);
      f << header;
      if (!f) {
        std::cerr << "lrchain-derive: cannot write " << tmp << "\n";
        return 1;
      }
    }
    fs::rename(tmp, target);
    if (!quiet) std::cout << "wrote " << target.string() << "\n";
  }
  if (!quiet) std::printf("derivation + checks + emission: %.2f s\n", seconds);
  return all_passed ? 0 : 1;
}

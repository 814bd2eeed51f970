#pragma once
// The computations of `lrchain reproduce`: one step per part of the paper. A step runs in-process
// (coefficients, intervals, thresholds) or runs `lrchain` subcommands whose outputs (JSON summary,
// data, gnuplot figures) go into its own sub-directory of the report, and returns the Section
// with the paper-vs-ours rows and the figures.
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "lrchain/params.hpp"
#include "report.hpp"

namespace lrchain::report {

struct StepContext {
  std::filesystem::path out;       // report directory being written
  std::filesystem::path exe;       // the lrchain executable (for subcommands)
  std::filesystem::path examples;  // directory of the experiment configs (examples/*.toml)
  bool full = false;               // paper sizes and times (else the quick variants)
  int child_threads = 1;           // OMP_NUM_THREADS of subcommands
};

struct Step {
  std::string id;                  // also the output sub-directory
  std::string title;
  double cost = 1;                 // CPU seconds of the quick step (measured), to start long steps first
  std::function<Section(const StepContext&)> run;
};

std::vector<Step> coefficient_steps();  // steps_coefficients.cpp: Secs. 2-5 frequencies, periods, speeds
std::vector<Step> regime_steps();       // steps_regime.cpp: Sec. 3.3 intervals, thresholds, Figs. 2-5
std::vector<Step> bright_steps();       // steps_bright.cpp: Sec. 4.2 experiments 1-5, Figs. 6-13
std::vector<Step> lattice_steps();      // steps_lattice.cpp: Sec. 4.3 drive, Sec. 5.1 modulated wave
std::vector<Step> dark_steps();         // steps_dark.cpp: Secs. 5.3-5.4 dark breathers, Figs. 17-25

// The paper's chain (Hertz exponent alpha = 3/2, kappa = 1) at precompression delta0 and mass ratio rho;
// delta0 defaults to the paper's 4/9.
inline Params paper_chain(double rho, double delta0 = 4.0 / 9.0) { return Params{1.5, delta0, 1.0, rho}; }

// All steps in report order.
std::vector<Step> all_steps();

}  // namespace lrchain::report

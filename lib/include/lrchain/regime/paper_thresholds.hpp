#pragma once
// The special mass ratios and precompressions quoted in Sec. 3.3 (focdef), as parameter scans
// whose regime events (regime_events.hpp) are matched to the printed values.
#include <string>
#include <vector>

#include "lrchain/regime/regime_events.hpp"

namespace lrchain::regime {

struct ThresholdScenario {
  std::string name;                 // e.g. "optical_rho"
  Branch branch = Branch::optical;
  ParameterAxis axis = ParameterAxis::rho;
  Params base;                      // the fixed parameters (kappa = 1, alpha = 3/2)
  GridAxis scan;                    // scanned range of the axis parameter
  std::vector<double> paper_values; // values printed in the paper
  std::string paper_text;           // where and how the paper states them
};

// Sec. 3.3: optical rho 2.356, 15.335, 22.298; acoustic rho 0.074, 2.137; optical delta0 ~0.22
// (rho = 3) and ~0.002 (rho = 17.8); acoustic delta0 ~0.06 (rho = 0.32).
std::vector<ThresholdScenario> paper_threshold_scenarios();

struct MatchedThreshold {
  double paper = 0;
  bool found = false;
  RegimeEvent event;  // the computed event closest to the paper value (relative distance)
};

std::vector<MatchedThreshold> match_paper_values(const ThresholdScenario& s,
                                                 const std::vector<RegimeEvent>& events);

}  // namespace lrchain::regime

#include "lrchain/regime/paper_thresholds.hpp"

#include <cmath>

namespace lrchain::regime {

std::vector<ThresholdScenario> paper_threshold_scenarios() {
  const Params paper{};  // alpha = 3/2, delta0 = 4/9, kappa = 1, rho = 1/3
  Params rho3 = paper, rho178 = paper, rho032 = paper;
  rho3.rho = 3.0;
  rho178.rho = 17.8;
  rho032.rho = 0.32;
  return {
      {"optical_rho", Branch::optical, ParameterAxis::rho, paper, {0.01, 40.0, 400, true},
       {2.356, 15.335, 22.298},
       "Sec. 3.3: 0<rho<2.356 one interval; h_tilde=0 for rho >~ 15.335; regions flip at "
       "rho ~ 2.356 and ~ 22.298 where boundary curves intersect (delta0=4/9)"},
      {"acoustic_rho", Branch::acoustic, ParameterAxis::rho, paper, {0.01, 10.0, 300, true},
       {0.074, 2.137},
       "Sec. 3.3: acoustic focusing region for 0.074 < rho < 2.137 (delta0=4/9)"},
      {"optical_delta0_rho3", Branch::optical, ParameterAxis::delta0, rho3, {1e-4, 1.0, 300, true},
       {0.22}, "Sec. 3.3, Fig. 4 left: focusing band splits in two above delta0 ~ 0.22 (rho=3)"},
      {"optical_delta0_rho17.8", Branch::optical, ParameterAxis::delta0, rho178,
       {1e-4, 1.0, 300, true}, {0.002},
       "Sec. 3.3, Fig. 4 right: 1 -> 2 focusing bands at delta0 ~ 0.002, then 2 -> 3 -> 4 -> 3 "
       "(rho=17.8)"},
      {"acoustic_delta0_rho0.32", Branch::acoustic, ParameterAxis::delta0, rho032,
       {1e-4, 1.0, 300, true}, {0.06},
       "Sec. 3.3, Fig. 5: acoustic modes all defocusing below delta0 ~ 0.06 (rho=0.32)"},
  };
}

std::vector<MatchedThreshold> match_paper_values(const ThresholdScenario& s,
                                                 const std::vector<RegimeEvent>& events) {
  std::vector<MatchedThreshold> out;
  for (double v : s.paper_values) {
    MatchedThreshold m{v, false, {}};
    double best = 1e300;
    for (const auto& e : events) {
      const double d = std::abs(std::log(e.value / v));
      if (d < best) {
        best = d;
        m.event = e;
        m.found = true;
      }
    }
    out.push_back(m);
  }
  return out;
}

}  // namespace lrchain::regime

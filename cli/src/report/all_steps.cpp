// The report's steps in the paper's order.
#include "steps.hpp"

namespace lrchain::report {

std::vector<Step> all_steps() {
  std::vector<Step> steps;
  for (auto part : {coefficient_steps(), regime_steps(), bright_steps(), lattice_steps(), dark_steps()})
    steps.insert(steps.end(), part.begin(), part.end());
  return steps;
}

}  // namespace lrchain::report

// The stage of localized structures in a series of counts (wave_fate.hpp, StructureStage).
#include <algorithm>

#include "lrchain/sim/wave/wave_fate.hpp"

namespace lrchain::sim::wave {

// A window holds structures when more than half its samples count one; the stage spans the held windows.
StructureStage structure_stage(const std::vector<double>& t, const std::vector<double>& count, Index window) {
  StructureStage stage;
  const Index n = Index(std::min(t.size(), count.size()));
  if (n == 0 || window < 1) return stage;
  const Index w = std::min(window, n);
  std::vector<double> sorted(std::size_t(w), 0.0);
  Index held = 0;  // samples with a structure in the window [i, i + w)
  for (Index k = 0; k < w; ++k) held += count[std::size_t(k)] > 0;
  for (Index i = 0; i + w <= n; ++i) {
    if (i > 0) held += Index(count[std::size_t(i + w - 1)] > 0) - Index(count[std::size_t(i - 1)] > 0);
    if (2 * held <= w) continue;
    Index first = i, last = i + w - 1;
    while (!(count[std::size_t(first)] > 0)) ++first;
    while (!(count[std::size_t(last)] > 0)) --last;
    if (!stage.found()) stage.from = t[std::size_t(first)];
    stage.until = t[std::size_t(last)];
    std::copy(count.begin() + std::ptrdiff_t(i), count.begin() + std::ptrdiff_t(i + w), sorted.begin());
    std::nth_element(sorted.begin(), sorted.begin() + w / 2, sorted.end());  // the upper median
    stage.count = std::max(stage.count, Index(sorted[std::size_t(w / 2)]));
  }
  return stage;
}

}  // namespace lrchain::sim::wave

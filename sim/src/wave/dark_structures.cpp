// Dark structures of a ring's energy envelope (dark_structures.hpp).
#include "lrchain/sim/wave/dark_structures.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace lrchain::sim::wave {

Index envelope_window(double theta) {
  const double wavelength = 2 * std::numbers::pi / std::abs(theta);
  const Index w = 2 * Index(std::floor(wavelength / 2)) + 1;
  return std::max<Index>(3, w);
}

DarkStructureScan::DarkStructureScan(Index sites, Index window)
    : window_(std::min(window, sites % 2 == 1 ? sites : sites - 1)),
      envelope_(std::size_t(sites)),
      sorted_(std::size_t(sites)),
      dip_(std::size_t(sites)) {
  candidates_.reserve(std::size_t(sites));
  structures_.reserve(std::size_t(sites));
}

Index DarkStructureScan::scan(const double* e) {
  const Index n = Index(envelope_.size()), h = window_ / 2;
  const auto at = [n](Index i) { return std::size_t(((i % n) + n) % n); };
  // a_n: the running mean of |e| over the window (periodic)
  double sum = 0;
  for (Index k = -h; k <= h; ++k) sum += std::abs(e[at(k)]);
  for (Index i = 0; i < n; ++i) {
    envelope_[std::size_t(i)] = sum / double(window_);
    sum += std::abs(e[at(i + h + 1)]) - std::abs(e[at(i - h)]);
  }
  const auto a = [&](Index i) { return envelope_[at(i)]; };
  std::copy(envelope_.begin(), envelope_.end(), sorted_.begin());
  std::nth_element(sorted_.begin(), sorted_.begin() + n / 2, sorted_.end());
  background_ = sorted_[std::size_t(n / 2)];
  candidates_.clear();
  structures_.clear();
  spread_ = 0;
  if (!(background_ > 0)) return 0;
  const double b = background_, level = (1 - kDarkDepth) * b, back = (1 - kDarkDepth / 2) * b;
  // Dips: runs of a < back (a return to the background ends one; a shoulder that wanders about the dip
  // level does not) that reach below level, walked once round the ring from a site above back (the
  // median site is).
  Index start = 0;
  while (a(start) < back) ++start;
  Index minimum = -1;
  for (Index i = start + 1; i <= start + n; ++i) {
    if (a(i) < back) {
      if (minimum < 0 || a(i) < a(minimum)) minimum = i;
      continue;
    }
    if (minimum < 0) continue;
    const double lowest = a(minimum);
    if (lowest < level) {
      // its depth and its width at half depth, L = b (1 - d / 2) = (b + min a) / 2 <= back
      const double half = (b + lowest) / 2;
      Index l = minimum, r = minimum;
      while (a(l - 1) < half) --l;
      while (a(r + 1) < half) ++r;
      DarkStructure s;
      s.centre = double(at(minimum));
      s.depth = 1 - lowest / b;
      const double left = double(l - 1) + (a(l - 1) - half) / (a(l - 1) - a(l));
      const double right = double(r) + (half - a(r)) / (a(r + 1) - a(r));
      s.width = right - left;
      s.left = s.centre - (double(minimum) - left);
      s.right = s.centre + (right - double(minimum));
      candidates_.push_back(s);
    }
    minimum = -1;
  }
  std::sort(candidates_.begin(), candidates_.end(),
            [](const DarkStructure& x, const DarkStructure& y) { return x.depth > y.depth; });
  const auto distance = [n](double x, double y) {
    const double d = std::fmod(std::abs(x - y), double(n));
    return std::min(d, double(n) - d);
  };
  // The background: sites outside every dip widened by its width on both sides.
  std::fill(dip_.begin(), dip_.end(), char(0));
  for (const DarkStructure& s : candidates_) {
    const Index from = Index(std::floor(s.left - s.width)), to = std::min(Index(std::ceil(s.right + s.width)), from + n - 1);
    for (Index i = from; i <= to; ++i) dip_[at(i)] = 1;
  }
  Index outside = 0;
  for (Index i = 0; i < n; ++i)
    if (!dip_[std::size_t(i)]) sorted_[std::size_t(outside++)] = envelope_[std::size_t(i)];
  if (outside < n / 2) {  // the dips fill half the ring: no background left to call intact
    spread_ = std::numeric_limits<double>::infinity();
    return 0;
  }
  const auto quantile = [&](Index k) {
    std::nth_element(sorted_.begin(), sorted_.begin() + k, sorted_.begin() + outside);
    return sorted_[std::size_t(k)];
  };
  const double q1 = quantile(outside / 4), q3 = quantile((3 * outside) / 4);
  spread_ = (q3 - q1) / b;
  if (spread_ > kDarkBackgroundSpread) return 0;
  // A structure is narrow against its spacing: at most kDarkWidthShare of the distance to the nearest dip.
  for (const DarkStructure& s : candidates_) {
    double spacing = double(n);
    for (const DarkStructure& o : candidates_)
      if (&o != &s) spacing = std::min(spacing, distance(s.centre, o.centre));
    if (s.width <= kDarkWidthShare * spacing) structures_.push_back(s);
  }
  return Index(structures_.size());
}

}  // namespace lrchain::sim::wave

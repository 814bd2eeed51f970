#pragma once
// A uniform (or geometric) axis of sample values for maps and parameter scans.
#include <cmath>

#include "lrchain/index.hpp"

namespace lrchain::regime {

struct GridAxis {
  double lo = 0, hi = 1;
  Index n = 2;             // number of points, both ends included (n >= 2)
  bool logarithmic = false;  // geometric spacing (lo > 0)

  double at(Index i) const {
    const double t = n > 1 ? static_cast<double>(i) / (n - 1) : 0.0;
    if (logarithmic) return lo * std::pow(hi / lo, t);
    return lo + (hi - lo) * t;
  }
};

// Throws InvalidParameter(name, ...) unless lo < hi, n >= 2 (and lo > 0 when logarithmic).
void validate(const GridAxis& axis, const char* name);

}  // namespace lrchain::regime

#pragma once
// The distance from a multiplier to the nearest of a set (windowed against dense Floquet spectra).
#include <algorithm>
#include <complex>
#include <limits>
#include <vector>

namespace lrchain::test {

inline double nearest(std::complex<double> l, const std::vector<std::complex<double>>& all) {
  double d = std::numeric_limits<double>::infinity();
  for (const auto& m : all) d = std::min(d, std::abs(l - m));
  return d;
}

}  // namespace lrchain::test

#pragma once
// Zeros of a smooth scalar function on an interval: bracketing from a fine sample, refinement
// with Boost.Math TOMS 748, and Brent minimisation to find close pairs hidden inside one cell.
#include <functional>
#include <span>
#include <vector>

#include "lrchain/index.hpp"

namespace lrchain::regime {

struct ZeroFindingOptions {
  Index samples = 2049;        // uniform sample points on [a, b] (including both ends)
  double x_tolerance = 1e-12;  // final bracket width of every zero
};

// All zeros of f in [a, b] found from its values fs at the points xs (ascending): each sign change
// between neighbours is refined by TOMS 748; at each interior local minimum of |f| without a sign
// change, Brent's minimiser probes whether f crosses zero twice inside the two cells around it.
// NaN samples are skipped. Returns the zeros in ascending order.
std::vector<double> find_zeros(const std::function<double(double)>& f, std::span<const double> xs,
                               std::span<const double> fs, double x_tolerance);

// Same, sampling f on `options.samples` uniform points of [a, b] first.
std::vector<double> find_zeros(const std::function<double(double)>& f, double a, double b,
                               const ZeroFindingOptions& options = {});

// One zero of f in [a, b] with f(a) f(b) < 0 by TOMS 748 to bracket width x_tolerance.
double solve_bracketed(const std::function<double(double)>& f, double a, double b, double fa,
                       double fb, double x_tolerance);

}  // namespace lrchain::regime

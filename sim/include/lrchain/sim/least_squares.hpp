#pragma once
// Least-squares slope of y(t): the speeds of Sec. 4 (energy centre, front, dark-breather centre).
#include <vector>

namespace lrchain::sim {

// Slope of the least-squares line through (t_i, y_i); 0 for fewer than 2 points or constant t.
double least_squares_slope(const std::vector<double>& t, const std::vector<double>& y);

}  // namespace lrchain::sim

// Least-squares slope (speeds of moving structures, Sec. 4).
#include "lrchain/sim/least_squares.hpp"

namespace lrchain::sim {

double least_squares_slope(const std::vector<double>& t, const std::vector<double>& y) {
  const double n = double(t.size());
  if (t.size() < 2) return 0;
  double st = 0, sy = 0, stt = 0, sty = 0;
  for (std::size_t i = 0; i < t.size(); ++i) {
    st += t[i]; sy += y[i]; stt += t[i] * t[i]; sty += t[i] * y[i];
  }
  const double den = n * stt - st * st;
  return den != 0 ? (n * sty - st * sy) / den : 0;
}

}  // namespace lrchain::sim

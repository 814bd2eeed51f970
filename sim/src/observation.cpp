// Observation times and displacement snapshots shared by the run observers (observation.hpp).
#include "observation.hpp"

#include <algorithm>
#include <cmath>

namespace lrchain::sim {

std::vector<double> merge_observation_times(std::vector<double> times,
                                            const std::vector<double>& extra, double scale) {
  times.insert(times.end(), extra.begin(), extra.end());
  std::sort(times.begin(), times.end());
  times.erase(std::unique(times.begin(), times.end(),
                          [&](double a, double b) { return std::abs(a - b) <= 1e-9 * scale; }),
              times.end());
  return times;
}

Snapshot displacement_snapshot(const StateLayout& L, const State& s, std::span<const double> e, double t,
                               std::string tag, Index first_label) {
  Snapshot snap;
  snap.t = t;
  snap.tag = std::move(tag);
  snap.names = {"n", "u", "v", "u_dot", "v_dot", "e"};
  const double *u = L.primary(s), *v = L.secondary(s), *ud = L.primary_rate(s),
               *vd = L.secondary_rate(s);
  for (Index i = 0; i < L.sites; ++i)
    snap.data.insert(snap.data.end(), {double(first_label + i), u[i], v[i], ud[i], vd[i],
                                       e[static_cast<std::size_t>(i)]});
  return snap;
}

}  // namespace lrchain::sim

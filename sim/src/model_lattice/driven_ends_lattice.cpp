// Model lattices with driven (prescribed) ends (driven_ends_lattice.hpp).
#include "driven_ends_lattice.hpp"

#include <algorithm>
#include <cstring>
#include <utility>

namespace lrchain::sim {

DrivenEndsLattice::DrivenEndsLattice(const lrchain_lattice_kernels& kernels, std::vector<double> parameters,
                                     std::size_t sites, LatticeForm form, EndMotion motion)
    : extended_(kernels, std::move(parameters), sites + 2 * kGhostSites, false, form),
      sites_(sites),
      motion_(std::move(motion)),
      q_(extended_.positions()),
      a_(extended_.positions()),
      left_(extended_.fields() * kGhostSites),
      right_(extended_.fields() * kGhostSites) {}

// The extended lattice's positions (ghost sites from the motion at t), its accelerations, the interior copied out.
void DrivenEndsLattice::acceleration(const double* q, double* a, double t) const {
  const std::size_t g = kGhostSites, m = sites_ + 2 * g;
  motion_(t, left_.data(), right_.data());
  for (std::size_t f = 0; f < fields(); ++f) {
    double* row = q_.data() + f * m;
    std::copy_n(left_.data() + f * g, g, row);
    std::copy_n(q + f * sites_, sites_, row + g);
    std::copy_n(right_.data() + f * g, g, row + g + sites_);
  }
  extended_.acceleration(q_.data(), a_.data());
  for (std::size_t f = 0; f < fields(); ++f) std::copy_n(a_.data() + f * m + g, sites_, a + f * sites_);
}

void DrivenEndsLattice::operator()(const State& s, State& ds, double t) const {
  const std::size_t n = positions();
  std::memcpy(ds.data(), s.data() + n, n * sizeof(double));
  acceleration(s.data(), ds.data() + n, t);
}

}  // namespace lrchain::sim

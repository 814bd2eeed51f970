#pragma once
// A model lattice whose ends are driven: `kGhostSites` sites beyond each end follow a prescribed
// motion (in the lattice's own variables, strain or displacement form) instead of the fixed or
// zero-strain ends of the kernels, e.g. the NLS ansatz itself (the "emitting" ends of Sec. 4.2).
// The interior runs on the generated kernels of a lattice extended by the ghost sites; the
// accelerations of the ghost sites are discarded. Not autonomous: integrate with rkf78 or dopri5.
#include <cstddef>
#include <functional>
#include <vector>

#include "lrchain/sim/model_lattice.hpp"

namespace lrchain::sim {

class DrivenEndsLattice {
 public:
  // Ghost sites per end: the reach of the kernels' stencil (shifts up to +-3, one more in strain form).
  static constexpr std::size_t kGhostSites = 4;
  // motion(t, left, right): the ghost variables at time t, field-major, kGhostSites per field each
  // (left[f * kGhostSites + k] is site k - kGhostSites, right[f * kGhostSites + k] site sites + k).
  using EndMotion = std::function<void(double t, double* left, double* right)>;

  DrivenEndsLattice(const lrchain_lattice_kernels& kernels, std::vector<double> parameters, std::size_t sites,
                    LatticeForm form, EndMotion motion);

  std::size_t sites() const { return sites_; }
  std::size_t fields() const { return extended_.fields(); }
  std::size_t positions() const { return fields() * sites_; }
  bool autonomous() const { return false; }

  // First-order system for Odeint: state [q q'] -> [q' q''] at time t.
  void operator()(const State& s, State& ds, double t) const;
  // Interior accelerations with the ghost sites at their prescribed positions at time t.
  void acceleration(const double* q, double* a, double t) const;

 private:
  CompiledLattice extended_;
  std::size_t sites_;
  EndMotion motion_;
  mutable std::vector<double> q_, a_, left_, right_;
};

}  // namespace lrchain::sim

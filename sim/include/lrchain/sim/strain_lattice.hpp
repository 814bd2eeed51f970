#pragma once
// The resonant granular chain in strain form (eq:Hertzd0S), x_n = u_n - u_{n-1}, y_n = v_n - v_{n-1}:
//   x_n'' = V'(x_{n+1}) - 2V'(x_n) + V'(x_{n-1}) - kappa (x_n - y_n),  rho y_n'' = kappa (x_n - y_n),
// on sites 0..sites-1 (the paper's n = -N..N) with zero-strain ends x_{-1} = x_{sites} = 0 (Sec. 4)
// or periodic ends. Reusable by any solver (bright runs, dark-breather shooting): the RHS works
// on contiguous arrays and allocates nothing.
#include <cstddef>
#include <vector>

#include "lrchain/index.hpp"
#include "lrchain/params.hpp"
#include "lrchain/sim/contact_law.hpp"
#include "lrchain/sim/state.hpp"

namespace lrchain::sim {

enum class StrainEnds { zero_strain, periodic };

// Not thread-safe: acceleration() is const but writes a scratch buffer of the object (no allocation
// per call); give each thread its own lattice.
class StrainLattice {
 public:
  // Throws InvalidParameter("sites", ...) for fewer than 2 sites.
  StrainLattice(const Params& p, Index sites, StrainEnds ends = StrainEnds::zero_strain);

  Index sites() const { return layout_.sites; }
  const StateLayout& layout() const { return layout_; }
  const Params& params() const { return params_; }
  const ContactLaw& law() const { return law_; }
  StrainEnds ends() const { return ends_; }

  // First-order system for Odeint: state [x y x' y'] -> derivative (eq:Hertzd0S).
  void operator()(const State& s, State& ds, double t) const;
  // Accelerations only: q = [x y] (2*sites), a = [x'' y''] (2*sites).
  void acceleration(const double* q, double* a) const;

 private:
  Params params_;
  ContactLaw law_;
  StateLayout layout_;
  StrainEnds ends_;
  mutable std::vector<double> force_;  // scratch V'(x_n) with one ghost entry on each side
};

}  // namespace lrchain::sim

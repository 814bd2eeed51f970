#pragma once
// A lattice of any model file, run through its generated kernels (lrchain/compiled_model_abi.h): periodic
// or fixed ends, displacement form or (translation-invariant models) strain form, with the
// first-order RHS for Boost.Odeint, the accelerations for the symplectic steppers, the Jacobian
// action for variational equations and the energy density. Nothing allocates after construction.
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "lrchain/index.hpp"
#include "lrchain/compiled_model_abi.h"
#include "lrchain/sim/state.hpp"

namespace lrchain::sim {

enum class LatticeForm { displacement, strain };

// The kernels compiled into lrchain for a shipped model (resonant_chain, fput, ...), or nullptr.
const lrchain_lattice_kernels* shipped_lattice_kernels(std::string_view model_name);
// Names of the shipped models with compiled-in kernels.
std::vector<std::string> shipped_lattice_models();

// Not thread-safe: the const methods write scratch buffers of the object (no allocation per call);
// give each thread its own CompiledLattice (copies are cheap next to a run).
class CompiledLattice {
 public:
  // `parameters` in the model file's order (kernels.parameter_names). Throws InvalidParameter for
  // fewer than 2 sites, a wrong parameter count, or the strain form of an on-site model.
  CompiledLattice(const lrchain_lattice_kernels& kernels, std::vector<double> parameters, Index sites,
               bool periodic, LatticeForm form);

  Index sites() const { return static_cast<Index>(sites_); }
  Index fields() const { return static_cast<Index>(kernels_->fields); }
  Index positions() const { return fields() * sites(); }  // entries of q (and of a)
  bool periodic() const { return periodic_; }
  LatticeForm form() const { return form_; }
  const std::vector<double>& masses() const { return masses_; }
  const std::vector<double>& parameters() const { return parameters_; }  // the model file's order
  const lrchain_lattice_kernels& kernels() const { return *kernels_; }

  // First-order system for Odeint: state [q q'] -> [q' q''].
  void operator()(const State& s, State& ds, double t) const;
  // Accelerations q -> q'' (fields() arrays of sites() entries each); autonomous (t unused).
  void acceleration(const double* q, double* a, double t = 0.0) const;
  bool autonomous() const { return true; }
  // Directional derivative of the accelerations at q along dq.
  void jacobian_action(const double* q, const double* dq, double* da) const;
  // Energy density e[n] (sites() entries) at positions q and velocities v; InvalidParameter when
  // the model's forces have no potential. Strain form with open ends: the conserved energy of the
  // free chain of beads -1..n-1 (lrchain/compiled_model_abi.h) in its centre-of-mass frame (bead -1's kinetic
  // term in e[0]); periodic strain rings are converted to displacements (u_0 summed from u_0[-1] = 0).
  void energy_density(const double* q, const double* velocity, double* e) const;
  double energy(const State& s) const;
  bool has_energy() const { return kernels_->energy_density != nullptr; }

  // Displacements and velocities (displacement form) of a strain-form state, for diagnostics.
  void displacements_of(const double* q, double* u) const;

 private:
  bool free_chain() const { return form_ == LatticeForm::strain && !periodic_; }

  const lrchain_lattice_kernels* kernels_;
  std::vector<double> parameters_, masses_;
  std::size_t sites_;
  bool periodic_;
  LatticeForm form_;
  lrchain_lattice_accelerations accelerations_;
  lrchain_lattice_jacobian_action jacobian_;
  mutable std::vector<double> work_, u_, v_, e_;
};

}  // namespace lrchain::sim

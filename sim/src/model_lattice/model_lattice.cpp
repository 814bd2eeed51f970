// A lattice of any model through its generated kernels (model_lattice.hpp).
#include "lrchain/sim/model_lattice.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <numeric>

#include "lrchain/errors.hpp"

namespace lrchain::sim {

CompiledLattice::CompiledLattice(const lrchain_lattice_kernels& kernels, std::vector<double> parameters, Index sites,
                           bool periodic, LatticeForm form)
    : kernels_(&kernels), parameters_(std::move(parameters)), sites_(sites), periodic_(periodic), form_(form) {
  if (kernels.abi_version != LRCHAIN_COMPILED_MODEL_ABI_VERSION)
    throw InvalidParameter("model", std::string(kernels.model_name) + ": lattice kernels of another version");
  if (sites < 2) throw InvalidParameter("sites", "a model lattice needs at least 2 sites");
  if (parameters_.size() != std::size_t(kernels.parameter_count))
    throw InvalidParameter("model", std::string(kernels.model_name) + " takes " + std::to_string(kernels.parameter_count) +
                                        " parameters, got " + std::to_string(parameters_.size()));
  if (form == LatticeForm::strain && !kernels.strain_accelerations)
    throw InvalidParameter("model", std::string(kernels.model_name) +
                                        " has on-site forces (not translation-invariant): it runs in displacement form only");
  accelerations_ = form == LatticeForm::strain ? kernels.strain_accelerations : kernels.displacement_accelerations;
  jacobian_ = form == LatticeForm::strain ? kernels.strain_jacobian_action : kernels.displacement_jacobian_action;
  masses_.resize(fields());
  kernels.masses(parameters_.data(), masses_.data());
  work_.assign(std::size_t(kernels.workspace_size(long(sites))), 0.0);
  u_.assign(positions(), 0.0);
  v_.assign(positions(), 0.0);
  e_.assign(sites, 0.0);
}

void CompiledLattice::acceleration(const double* q, double* a, double /*t*/) const {
  accelerations_(parameters_.data(), long(sites_), periodic_, q, a, work_.data());
}

void CompiledLattice::jacobian_action(const double* q, const double* dq, double* da) const {
  jacobian_(parameters_.data(), long(sites_), periodic_, q, dq, da, work_.data());
}

void CompiledLattice::operator()(const State& s, State& ds, double /*t*/) const {
  const std::size_t n = positions();
  std::memcpy(ds.data(), s.data() + n, n * sizeof(double));
  acceleration(s.data(), ds.data() + n);
}

// u_0[n] = sum_{j <= n} r[j], u_f = u_0 + w_f (strain form); a copy in displacement form.
void CompiledLattice::displacements_of(const double* q, double* u) const {
  const std::size_t n = sites_;
  if (form_ == LatticeForm::displacement) {
    std::memcpy(u, q, positions() * sizeof(double));
    return;
  }
  std::partial_sum(q, q + n, u);
  for (Index f = 1; f < fields(); ++f)
    for (std::size_t i = 0; i < n; ++i) u[f * n + i] = u[i] + q[f * n + i];
}

void CompiledLattice::energy_density(const double* q, const double* velocity, double* e) const {
  if (!has_energy())
    throw InvalidParameter("model", std::string(kernels_->model_name) + ": its forces do not derive from a potential, so it has no energy");
  displacements_of(q, u_.data());
  displacements_of(velocity, v_.data());
  if (!free_chain()) {
    kernels_->energy_density(parameters_.data(), long(sites_), periodic_ ? LRCHAIN_LATTICE_ENDS_PERIODIC : LRCHAIN_LATTICE_ENDS_FIXED,
                             u_.data(), v_.data(), e, work_.data());
    return;
  }
  // Strain form, open ends: the free chain of beads -1..n-1 (bead -1 of field 0 only), displacements
  // and velocities measured from bead -1. Its total momentum is conserved, so the conserved energy
  // computable from relative velocities is the centre-of-mass one: potential + (1/2) sum_k m_k (v_k - V)^2.
  double momentum = 0, mass = masses_[0];
  for (Index f = 0; f < fields(); ++f) {
    const double field_mass = masses_[std::size_t(f)];
    momentum += field_mass * std::accumulate(v_.begin() + f * sites(), v_.begin() + (f + 1) * sites(), 0.0);
    mass += field_mass * double(sites());
  }
  const double centre_velocity = momentum / mass;
  for (double& v : v_) v -= centre_velocity;
  kernels_->energy_density(parameters_.data(), long(sites_), LRCHAIN_LATTICE_ENDS_FREE, u_.data(), v_.data(), e, work_.data());
  e[0] += 0.5 * masses_[0] * centre_velocity * centre_velocity;  // bead -1
}

double CompiledLattice::energy(const State& s) const {
  energy_density(s.data(), s.data() + positions(), e_.data());
  return std::accumulate(e_.begin(), e_.end(), 0.0);
}

}  // namespace lrchain::sim

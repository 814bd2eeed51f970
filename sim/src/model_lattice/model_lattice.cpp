// A lattice of any model through its generated kernels (model_lattice.hpp).
#include "lrchain/sim/model_lattice.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <numeric>

#include "lrchain/errors.hpp"

namespace lrchain::sim {

ModelLattice::ModelLattice(const lrchain_lattice_kernels& kernels, std::vector<double> parameters, Index sites,
                           bool periodic, LatticeForm form)
    : kernels_(&kernels), parameters_(std::move(parameters)), sites_(sites), periodic_(periodic), form_(form) {
  if (kernels.abi_version != LRCHAIN_LATTICE_ABI_VERSION)
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
  const std::size_t energy_sites = free_chain() ? sites + kFreeEndGhosts : sites;
  work_.assign(std::size_t(std::max(kernels.workspace_size(long(sites)), kernels.workspace_size(long(energy_sites)))), 0.0);
  u_.assign(fields() * energy_sites, 0.0);
  v_.assign(fields() * energy_sites, 0.0);
  e_.assign(sites, 0.0);
  chain_e_.assign(free_chain() ? energy_sites : 0, 0.0);
  if (free_chain()) left_bead_moves_ = left_bead_feels_chain();
}

// Probe of the strain form's left end: strain r[0] = delta alone shifts bead -1 against the whole
// chain; the sum of the strain accelerations is a_0[last] - a_0[-1] = -a_0[-1] when the last site is
// beyond the bonds' reach. Zero: bead -1 feels no force (its bonds reach ghosts only, as in the
// diatomic chain), so it moves uniformly and is a wall in its own frame.
bool ModelLattice::left_bead_feels_chain() const {
  const long probe_sites = 2 * long(kFreeEndGhosts);
  std::vector<double> q(fields() * std::size_t(probe_sites), 0.0), a(q.size());
  std::vector<double> work(std::size_t(kernels_->workspace_size(probe_sites)));
  q[0] = 1e-3;
  accelerations_(parameters_.data(), probe_sites, 0, q.data(), a.data(), work.data());
  const double sum = std::accumulate(a.begin(), a.begin() + probe_sites, 0.0);
  return std::abs(sum) > 1e-6 * std::abs(a[0]);
}

void ModelLattice::acceleration(const double* q, double* a, double /*t*/) const {
  accelerations_(parameters_.data(), long(sites_), periodic_, q, a, work_.data());
}

void ModelLattice::jacobian_action(const double* q, const double* dq, double* da) const {
  jacobian_(parameters_.data(), long(sites_), periodic_, q, dq, da, work_.data());
}

void ModelLattice::operator()(const State& s, State& ds, double /*t*/) const {
  const std::size_t n = positions();
  std::memcpy(ds.data(), s.data() + n, n * sizeof(double));
  acceleration(s.data(), ds.data() + n);
}

// u_0[n] = sum_{j <= n} r[j], u_f = u_0 + w_f (strain form); a copy in displacement form.
void ModelLattice::displacements_of(const double* q, double* u) const {
  const std::size_t n = sites_;
  if (form_ == LatticeForm::displacement) {
    std::memcpy(u, q, positions() * sizeof(double));
    return;
  }
  std::partial_sum(q, q + n, u);
  for (Index f = 1; f < fields(); ++f)
    for (std::size_t i = 0; i < n; ++i) u[f * n + i] = u[i] + q[f * n + i];
}

// Displacements of the strain form's free-free chain on sites + kFreeEndGhosts sites (stride): u_0
// summed from bead -1 (u_0[-1] = 0), every field of the ghost sites right of the chain at u_0[n-1]
// (zero strains beyond the right end).
void ModelLattice::free_chain_displacements(const double* q, double* u) const {
  const std::size_t n = sites_, stride = sites_ + kFreeEndGhosts;
  std::partial_sum(q, q + n, u);
  for (Index f = 1; f < fields(); ++f)
    for (std::size_t i = 0; i < n; ++i) u[f * stride + i] = u[i] + q[f * n + i];
  for (Index f = 0; f < fields(); ++f) std::fill(u + f * stride + n, u + (f + 1) * stride, u[n - 1]);
}

void ModelLattice::energy_density(const double* q, const double* velocity, double* e) const {
  if (!has_energy())
    throw InvalidParameter("model", std::string(kernels_->model_name) + ": its forces do not derive from a potential, so it has no energy");
  if (!free_chain()) {
    displacements_of(q, u_.data());
    displacements_of(velocity, v_.data());
    kernels_->energy_density(parameters_.data(), long(sites_), periodic_, u_.data(), v_.data(), e, work_.data());
    return;
  }
  // Strain form, open ends: the chain of beads -1..n-1 (bead -1 of field 0 only) with free ends.
  // Its total momentum is conserved, so the conserved energy computable from relative velocities is
  // the centre-of-mass one: potential + (1/2) sum_k m_k (v_k - V)^2, bead -1 at relative velocity 0
  // (V = 0 when bead -1 feels no force: the frame of bead -1 is then inertial).
  const std::size_t n = sites_, stride = sites_ + kFreeEndGhosts;
  free_chain_displacements(q, u_.data());
  free_chain_displacements(velocity, v_.data());
  double momentum = 0, mass = masses_[0];
  for (Index f = 0; f < fields(); ++f) {
    momentum += masses_[f] * std::accumulate(v_.begin() + long(f * stride), v_.begin() + long(f * stride + n), 0.0);
    mass += masses_[f] * double(n);
  }
  const double centre_velocity = left_bead_moves_ ? momentum / mass : 0.0;
  for (Index f = 0; f < fields(); ++f) {
    double* v = v_.data() + f * stride;
    for (std::size_t i = 0; i < n; ++i) v[i] -= centre_velocity;
    std::fill(v + n, v + stride, 0.0);
  }
  // The kernel's fixed wall sits beyond the last ghost: its bond lands in the dropped ghost entries,
  // the ghost-ghost bonds have zero argument.
  kernels_->energy_density(parameters_.data(), long(stride), 0, u_.data(), v_.data(), chain_e_.data(), work_.data());
  std::copy(chain_e_.begin(), chain_e_.begin() + long(n), e);
  e[0] += 0.5 * masses_[0] * centre_velocity * centre_velocity;  // bead -1
}

double ModelLattice::energy(const State& s) const {
  energy_density(s.data(), s.data() + positions(), e_.data());
  return std::accumulate(e_.begin(), e_.end(), 0.0);
}

}  // namespace lrchain::sim

#pragma once
// The linear Bloch modes of a model lattice at a carrier wavenumber, read from its generated
// Jacobian at rest: the ansatz u_f[n] = Re(K_f e^{i(n theta - omega t)}) of every plane wave, ring
// and breather run, with no symbolic derivation in between.
#include <array>
#include <complex>
#include <cstddef>
#include <vector>

#include "lrchain/model.hpp"
#include "lrchain/compiled_model_abi.h"

namespace lrchain::sim {

struct BlochMode {
  double omega = 0;                             // frequency of the branch
  std::vector<std::complex<double>> kernel;     // Bloch vector per field, kernel[0] = 1; empty where the first field is at rest
};

// Every branch's mode at theta, in increasing frequency (the branch order of the model file). A mode
// whose first field does not move has an empty kernel (the NLS amplitude is undefined there; e.g. the
// light beads of a diatomic chain's acoustic mode at theta = pi). Throws InvalidParameter("theta", ...)
// where a branch frequency is not real and positive.
std::vector<BlochMode> bloch_modes(const lrchain_lattice_kernels& kernels, const std::vector<double>& parameters,
                                   double theta);

// The branch frequencies alone (increasing), with no condition on the kernel.
std::vector<double> branch_frequencies(const lrchain_lattice_kernels& kernels, const std::vector<double>& parameters,
                                       double theta);

// The linear band [min, max] of branch `branch`'s frequency over theta in [0, pi], sampled at theta = pi k /
// samples (k = 0..samples); a frequency squared below 0 (an acoustic branch at theta = 0) counts as 0.
std::array<double, 2> branch_band(const lrchain_lattice_kernels& kernels, const std::vector<double>& parameters,
                                  Index branch, Index samples = 256);

// Branch `branch` of bloch_modes, checked against the model's own dispersion relation: throws
// NumericalFailure when the lattice kernels and the coefficient evaluators disagree on omega by
// more than 1e-9 (relative): they would not describe the same lattice; InvalidParameter("theta")
// when that branch's first field is at rest.
BlochMode bloch_mode(const Model& model, const lrchain_lattice_kernels& kernels, Index branch, double theta);

// The lattice parameters of `model` (its first parameter_count inputs, in the file's order).
std::vector<double> lattice_parameters(const Model& model);

// The compiled-in lattice kernels of `model` when it is a shipped model file (same name and file
// hash), else nullptr.
const lrchain_lattice_kernels* compiled_in_lattice_kernels(const Model& model);

// The compiled-in lattice kernels of `model`, or InputError naming the model when there are none. A
// user's model file has its lattice code compiled at run time instead (compile_model_lattice of the
// model compiler; jobs::ModelSource::lattice picks either).
const lrchain_lattice_kernels& lattice_kernels_of(const Model& model);

}  // namespace lrchain::sim

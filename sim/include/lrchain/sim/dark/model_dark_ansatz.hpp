#pragma once
// Dark breathers of any model file: the theta = pi band edge where the model's NLS is defocusing
// and the stationary dark-breather seed built from its derived coefficients (eq:defocus_app,
// eq:xy_app generalised): displacements
//   u_f[n](0) = (M + 2 K_f (-1)^n) A tanh(eta (n - n0)),
// A = sqrt(3 (omega_b - omega) / h_tilde), eta = sqrt(3 (omega_b - omega) / omega''), K the
// lattice's own Bloch vector at theta = pi (model_lattice_bloch.hpp), and the mean-flow factor
// M = -lambda sqrt(omega'' h_tilde) / |h_tilde| of translation-invariant models (on-site models
// have no mean flow, M = 0). For the resonant chain this is exactly make_dark_breather_ansatz.
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "lrchain/ansatz/dark_breather.hpp"
#include "lrchain/model.hpp"
#include "lrchain/sim/model_lattice_abi.h"

namespace lrchain::sim::dark {

struct ModelDarkAnsatz {
  std::size_t branch = 0;
  double theta = 0;               // pi: the edge the breather bifurcates from
  double omega_b = 0;             // breather frequency, on the side of the edge where A is real
  double omega = 0;               // edge frequency
  double curvature = 0;           // omega'' at the edge
  double h_tilde = 0;             // h - lambda beta (h for on-site models)
  double lambda = 0;              // 0 without mean flow
  double amplitude = 0;           // A
  double inverse_width = 0;       // eta
  double mean_factor = 0;         // M
  std::vector<double> kernel;     // Bloch vector K_f (real at theta = pi), K_0 = 1
  bool mean_flow = false;         // strain form (translation-invariant) or displacement form
};

// The branch (given, or the first in the file's order) whose theta = pi edge is defocusing
// (omega'' h_tilde > 0). InvalidParameter("branch", ...) naming every edge checked and its regime
// when there is none.
std::size_t defocusing_edge(const Model& model, std::optional<std::size_t> branch);

// The seed's coefficients at omega_b. InvalidParameter("omega-b", ...) unless
// (omega_b - omega) h_tilde > 0 and omega_b > 0.
ModelDarkAnsatz make_model_dark_ansatz(const Model& model, const lrchain_lattice_kernels& kernels,
                                       std::size_t branch, double omega_b);

// Z(0) on an odd periodic ring of `sites` (centre in the middle, n = i - (sites - 1)/2) in the
// lattice's variables: strains r[n] = u_0[n] - u_0[n-1], w_f[n] = u_f[n] - u_0[n] (mean flow) or
// displacements u_f[n], field-major.
Eigen::VectorXd model_dark_seed(const ModelDarkAnsatz& ansatz, DarkCenter center, int sites);

}  // namespace lrchain::sim::dark

#pragma once
// Dark breathers of any model file: a band edge (theta = pi, else theta = 0) where the model's NLS
// is defocusing and the stationary dark-breather seed built from its derived coefficients
// (eq:defocus_app, eq:xy_app generalised): at theta = pi, on an odd periodic ring, displacements
//   u_f[n](0) = (M + 2 K_f (-1)^n) A tanh(eta (n - n0)),
// A = sqrt((omega_b - omega) / h), eta = sqrt(h_tilde A^2 / omega''), K the
// lattice's own Bloch vector at theta = pi (model_lattice_bloch.hpp), and the mean-flow factor
// M = -lambda sqrt(omega'' h_tilde) / |h_tilde| of translation-invariant models (on-site models
// have no mean flow, M = 0). h is the background's coefficient (omega_b - omega = h A^2 with the
// far-field mean strain fixed to zero); for the resonant chain at alpha = 3/2, h_tilde = 3 h and this
// is make_dark_breather_ansatz's A = sqrt(3 (omega_b - omega)/h_tilde), eta = sqrt(3 (omega_b - omega)/omega'').
// At theta = 0 the carrier does not change sign from site to site, so a single dark breather does
// not fit a periodic ring: the seed is a pair of dark breathers half a ring apart on an even ring,
//   u_f[n](0) = M A (tanh(eta (n - n1)) + tanh(eta (n - n2))) - 2 K_f A tanh(eta (n - n1)) tanh(eta (n - n2)),
// n1 = N/4 + n0, n2 = n1 + N/2 (array index n).
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "lrchain/index.hpp"
#include "lrchain/ansatz/dark_breather.hpp"
#include "lrchain/model.hpp"
#include "lrchain/compiled_model_abi.h"

namespace lrchain::sim::dark {

struct DarkAnsatz {
  Index branch = 0;
  double theta = 0;               // pi: the edge the breather bifurcates from
  double omega_b = 0;             // breather frequency, on the side of the edge where A is real
  double omega = 0;               // edge frequency
  double curvature = 0;           // omega'' at the edge
  double h = 0;                   // omega_b - omega = h A^2: the background with zero far-field mean strain
  double h_tilde = 0;             // h - lambda beta (h for on-site models)
  double lambda = 0;              // 0 without mean flow
  double amplitude = 0;           // A
  double inverse_width = 0;       // eta
  double mean_factor = 0;         // M
  std::vector<double> kernel;     // Bloch vector K_f (real at theta = pi), K_0 = 1
  bool mean_flow = false;         // strain form (translation-invariant) or displacement form
};

struct DefocusingEdge {
  Index branch = 0;
  double theta = 0;  // pi or 0
};

// The NLS regime at the band edge theta (0 or pi) of `branch`: the regime (singular where the branch
// has no coefficients there or h_tilde diverges at the edge) and its text for messages, e.g.
// "focusing (omega'' h_tilde = -0.0312)" or "no real positive frequency". Bright breathers use it too.
std::string band_edge_regime(const Model& model, Index branch, double theta, Regime& regime);

// The branch (given, or the first in the file's order) and edge (theta = pi first, then theta = 0)
// where the NLS is defocusing (omega'' h_tilde > 0). InvalidParameter("branch", ...) naming every
// edge checked and its regime when there is none.
DefocusingEdge defocusing_edge(const Model& model, std::optional<Index> branch);

// The seed's coefficients at omega_b. InvalidParameter("omega_b", ...) unless
// (omega_b - omega) h > 0 and omega_b > 0: with the far-field mean strain fixed to zero the
// background's frequency is omega + h A^2 (h, not h_tilde); InvalidParameter("branch", ...) when
// h = 0 or is not finite there.
DarkAnsatz make_dark_ansatz(const Model& model, const lrchain_lattice_kernels& kernels,
                                       const DefocusingEdge& edge, double omega_b);

// InvalidParameter("sites", ...) unless `sites` >= 9 fits the edge: odd at theta = pi, even at 0.
void check_dark_sites(const DarkAnsatz& ansatz, Index sites);

// Z(0) on a periodic ring of `sites` (theta = pi: centre in the middle, n = i - (sites - 1)/2;
// theta = 0: the pair) in the lattice's variables: strains r[n] = u_0[n] - u_0[n-1],
// w_f[n] = u_f[n] - u_0[n] (mean flow) or displacements u_f[n], field-major.
Eigen::VectorXd dark_seed(const DarkAnsatz& ansatz, DarkCenter center, Index sites);

// The same seed half a period T_b/2 later: the carrier's sign reversed (K_f -> -K_f), the mean flow kept.
Eigen::VectorXd dark_seed_half_period(const DarkAnsatz& ansatz, DarkCenter center, Index sites);

// The seed's centre as an array position: (sites - 1)/2 + n0 at theta = pi, the first of the pair's
// sites/4 + n0 at theta = 0 (the reflection about it maps the second onto itself).
double dark_seed_centre(const DarkAnsatz& ansatz, DarkCenter center, Index sites);

}  // namespace lrchain::sim::dark

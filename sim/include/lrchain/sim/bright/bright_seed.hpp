#pragma once
// The band edge an exact bright breather of a model file bifurcates from, and its seed: the NLS
// bright-breather ansatz with the derivation's second-order terms (ModelBrightAnsatz,
// bright_run.hpp; eq:focus_app generalised) at that edge, stationary (c = 0 at theta = 0, pi),
// at t = 0 (a turning point: all velocities zero, as the time-reversible shooting needs),
//   u_f[n](0) = M1 tanh(z) + 2 M2 sech(z) K_f cos(n theta) + 2 M2^2 sech^2(z) Re(W2_f e^{2 i n theta}) + ...,
// z = a (n - n0), M2 = sqrt(2 (omega_b - omega) / h_tilde), a = sqrt(2 (omega - omega_b) / omega''),
// on a periodic ring of `sites` sites with the centre n0 at the middle: site-centred (n0 = 0) or
// bond-centred (n0 = 1/2), in the lattice's variables (strains of translation-invariant models,
// displacements of on-site ones).
#include <optional>
#include <string>

#include <Eigen/Dense>

#include "lrchain/ansatz/dark_breather.hpp"
#include "lrchain/coefficients.hpp"
#include "lrchain/index.hpp"
#include "lrchain/model.hpp"
#include "lrchain/sim/bright_run.hpp"
#include "lrchain/compiled_model_abi.h"

namespace lrchain::sim::bright {

struct FocusingEdge {
  Index branch = 0;
  double theta = 0;  // pi or 0
  NlsCoefficients nls;
};

// The edge of a bright breather at omega_b: among the band edges (theta = pi, 0 of every branch, or of
// `branch` when given) where the NLS is focusing (omega'' h_tilde < 0) and omega_b lies on the side
// where the breather leaves the band ((omega_b - omega) h_tilde > 0), the one nearest omega_b.
// InvalidParameter("omega_b", ...) listing every edge checked, its regime and side, when there is none.
FocusingEdge focusing_edge(const Model& model, std::optional<Index> branch, double omega_b);

// The first focusing band edge of `branch` (none: of every branch in the file's order), theta = pi before
// theta = 0: where a sweep that starts each breather a fixed distance from its edge places omega_b,
// omega + sign(h_tilde) x offset. InvalidParameter("branch", ...) listing every edge checked when there is none.
FocusingEdge first_focusing_edge(const Model& model, std::optional<Index> branch);

// The NLS ansatz at `edge` for omega_b (second-order terms included), its envelope centred at
// n0 = 0 (site) or 1/2 (bond; the carrier e^{i n theta} stays on the sites).
ModelBrightAnsatz bright_ansatz(const Model& model, const lrchain_lattice_kernels& kernels, const FocusingEdge& edge,
                                double omega_b, DarkCenter center);

// Z(0) of the ansatz on a ring of odd `sites`: site i is n = i - (sites - 1)/2, variables field-major;
// strains r[n] = u_0[n] - u_0[n-1] and w_f[n] = u_f[n] - u_0[n] when mean_flow, else displacements u_f[n].
Eigen::VectorXd bright_seed(const ModelBrightAnsatz& ansatz, bool mean_flow, Index fields, Index sites);

// InvalidParameter("sites", ...) unless sites >= 9 and odd (the middle site is the centre n = 0).
void check_bright_sites(Index sites);

}  // namespace lrchain::sim::bright

#pragma once
// Stationary dark-breather approximation of the strain lattice at a theta = pi band edge
// (eq:defocus_app with c = 0, eq:xy_app): the Newton seed of Sec. 5.3.
#include <vector>

#include "lrchain/coefficients.hpp"
#include "lrchain/dispersion.hpp"
#include "lrchain/index.hpp"
#include "lrchain/params.hpp"

namespace lrchain {

// Centre of the dark breather: n0 = 0 (site-centred) or n0 = 1/2 (bond-centred), Sec. 5.2.
enum class DarkCenter { site, bond };
std::string_view to_string(DarkCenter c);
DarkCenter parse_dark_center(std::string_view text);  // "site" | "bond"; InvalidParameter("center")
inline double dark_center_n0(DarkCenter c) { return c == DarkCenter::site ? 0.0 : 0.5; }

struct DarkBreatherAnsatz {
  Branch edge = Branch::optical;  // band whose theta = pi edge the breather bifurcates from
  double omega_b = 0;             // breather frequency (eq:xy_app), on the gap side of the edge
  double omega = 0;               // edge frequency omega_+-(pi) (eq:disp1d)
  double curvature = 0;           // omega''(pi) (eq:ppOmega)
  double h_tilde = 0;             // (eq:h_tilde) at pi
  double lambda = 0;              // mean-flow factor (eq:lambda) at pi
  double amplitude = 0;           // sqrt(3 (omega_b - omega) / h_tilde)
  double inverse_width = 0;       // eta = sqrt(3 (omega_b - omega) / omega'')
  // Mean-flow prefactor M3/M4 = -lambda sqrt(omega'' h_tilde)/|h_tilde| (eq:defocus_app);
  // equals -2/sqrt(3) for alpha = 3/2, delta0 = 4/9 as printed in eq:xy_app.
  double mean_factor = 0;
  double resonator_factor = 0;    // kappa / (kappa - rho omega^2) (eq:xy_app, y component)
};

// Throws InvalidParameter("omega_b", ...) unless omega_b lies on the gap side of the edge
// (omega_b < omega(pi)) and the edge is defocusing (omega'' h_tilde > 0).
DarkBreatherAnsatz make_dark_breather_ansatz(const Params& p, Branch edge, double omega_b);

// Strains x_n(t), y_n(t) of eq:xy_app at sites n = n_first .. n_first + sites - 1 (physical index,
// the difference operator d^- uses n - 1), centred at n0 = dark_center_n0(center).
void dark_breather_strains(const DarkBreatherAnsatz& a, DarkCenter center, Index n_first, Index sites,
                           double t, std::vector<double>& x, std::vector<double>& y);

}  // namespace lrchain

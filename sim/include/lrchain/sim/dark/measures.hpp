#pragma once
// Characterisation of a dark breather Z(0) (Sec. 5.3): vertical centres C_x, C_y (eq:center),
// amplitudes K_x, K_y (eq:amp) at the far site i = 0, the renormalised l2 norm (eq:l2norm) and the
// relative error E_b(t) (eq:relerr), from a direct integration of eq:Hertzd0S.
#include <Eigen/Dense>
#include <functional>
#include <vector>

#include "lrchain/index.hpp"
#include "lrchain/params.hpp"
#include "lrchain/sim/dark/contact_integrator.hpp"

namespace lrchain::sim::dark {

struct DarkMeasures {
  double norm_squared = 0;  // ||Z(0)||^2 of eq:l2norm
  double K_x = 0, K_y = 0;  // eq:amp at the far site (the paper's site 1: far from the centre)
  double C_x = 0, C_y = 0;  // eq:center at the far site
  double E_b = 0;           // E_b(T_b) of eq:relerr
  double max_strain = 0;    // max_n,t x_n(t) (> delta0: beads lose contact)
};

// Advances an orbit state [positions, velocities] in place from t0 to t1 (any lattice).
using OrbitAdvance = std::function<void(std::vector<double>& state, double t0, double t1)>;

// The measures of one period of an orbit from Z(0) = z0 (positions of `fields` variables of `sites`
// sites each, field-major; Zdot(0) = 0): variable 0 gives K_x, C_x and max_strain, variable 1 (if
// any) K_y, C_y; the l2 norm sums over all variables.
DarkMeasures measure_dark_orbit(const OrbitAdvance& advance, const Eigen::VectorXd& z0, Index sites, double omega_b,
                                Index samples = 400);

// Integrates one period from Z(0) (Zdot(0) = 0), sampling x_0, y_0 at >= `samples` times.
DarkMeasures measure_dark_breather(const Params& p, const Eigen::VectorXd& z0, double omega_b,
                                   const ContactIntegrationOptions& integration = {},
                                   Index samples = 400);

struct RelativeErrorSample {
  double t;    // m T_b
  double E_b;  // ||Z(m T_b) - Z(0)||_inf / ||Z(0)||_inf (eq:relerr)
};

// E_b(m T_b) for m = 1 .. floor(t_end / T_b) by direct integration (long-time check, Sec. 5.4).
std::vector<RelativeErrorSample> relative_error_history(const Params& p, const Eigen::VectorXd& z0,
                                                        double omega_b, double t_end,
                                                        const ContactIntegrationOptions& integration = {});

// Snapshots Z(t_k) of a direct integration (for space-time figures), t_k = k * dt, k = 0..steps.
std::vector<Eigen::VectorXd> dark_breather_evolution(const Params& p, const Eigen::VectorXd& z0,
                                                     double dt, Index steps,
                                                     const ContactIntegrationOptions& integration = {});

}  // namespace lrchain::sim::dark

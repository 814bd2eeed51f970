#pragma once
// Space-time evolution from an exact dark breather Z(0) (Sec. 5.4, Figs. 21, 22, 25): direct
// integration of eq:Hertzd0S (periodic ends, Zdot(0) = 0) to t_end, with per period m = 1..M
// the stroboscopic strains Z(m T_b), E_b(m T_b) (eq:relerr), the vertical centre C_x (eq:center,
// far site i = 0, over [(m-1) T_b, m T_b]) and the position of the breather (the dip of the
// oscillation amplitude; our measure, the paper gives none - see docs/dark-breathers.md).
#include <Eigen/Dense>
#include <atomic>
#include <functional>
#include <vector>

#include "lrchain/index.hpp"
#include "lrchain/params.hpp"
#include "lrchain/sim/dark/contact_integrator.hpp"
#include "lrchain/sim/dark/measures.hpp"

namespace lrchain::sim::dark {

struct DarkEvolutionPeriod {
  double t = 0;          // m T_b
  double E_b = 0;        // ||Z(m T_b) - Z(0)||_inf / ||Z(0)||_inf (eq:relerr)
  double C_x = 0;        // (sup + inf)/2 of x_0 over the period (eq:center)
  double K_x = 0;        // (sup - inf)/2 of x_0 over the period (eq:amp)
  double position = 0;   // breather position over the period, physical site n (unwrapped)
  double depth = 0;      // max_n A_n - min_n A_n of the amplitudes A_n over the period
};

struct DarkEvolution {
  Index sites = 0;
  double period = 0;                      // T_b
  std::vector<Eigen::VectorXd> snapshots;  // Z(m T_b), m = 0..M (snapshots[0] = Z(0))
  std::vector<DarkEvolutionPeriod> periods;  // m = 1..M
  double max_strain = 0;                  // max x_n(t) sampled (> delta0: contact lost)
};

// Position of the dark dip from the amplitudes A_n (array index i): circular mean of
// i weighted by (max A - A_i)^2, returned as a physical site n = i - (N - 1)/2 in (-N/2, N/2].
double dark_dip_position(const Eigen::VectorXd& amplitude);

// `perturbation` (empty: none): added to the start [Z(0), 0] (positions then velocities), so that an
// instability can be watched; E_b(m T_b) still measures the distance from the breather Z(0).
// The same for any orbit: Z(0) = z0 holds the positions of all variables (`sites` per variable,
// field-major); the amplitudes, centre and position use variable 0. `progress` (empty: none) is
// called after every period with the periods done / periods.
DarkEvolution evolve_dark_orbit(const OrbitAdvance& advance, const Eigen::VectorXd& z0, Index sites, double omega_b,
                                double t_end, Index samples_per_period, const std::atomic<bool>* stop = nullptr,
                                const std::function<void(double fraction)>& progress = {},
                                const Eigen::VectorXd& perturbation = {});

// Integrates from Z(0) over floor(t_end / T_b) periods, sampling every site `samples_per_period`
// times per period for the amplitudes A_n = (sup - inf)/2 of x_n(t) (the position measure).
// When *stop is set (e.g. by SIGINT) the integration ends after the current period.
DarkEvolution evolve_dark_breather(const Params& p, const Eigen::VectorXd& z0, double omega_b,
                                   double t_end, Index samples_per_period = 24,
                                   const ContactIntegrationOptions& integration = {},
                                   const std::atomic<bool>* stop = nullptr,
                                   const std::function<void(double fraction)>& progress = {},
                                   const Eigen::VectorXd& perturbation = {});

}  // namespace lrchain::sim::dark

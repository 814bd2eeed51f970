#pragma once
// Floquet multipliers of a bright breather on a large lattice from its core window, certified on the
// full lattice. Far from the core the breather's lattice is linear and at rest: its multipliers there
// are the phonon band's exp(+-i omega(q) T_b), on the unit circle, with extended eigenvectors; the
// instabilities and internal modes of the breather are localized at its core. So:
//   1. window: the sites where the profile exceeds `fraction` of its peak, plus `margin` on each side
//      (at most `cap` sites), as a ring of the same model with the breather restricted to it; its dense
//      monodromy (DarkShooting::monodromy) and eigenpairs (Eigen). A second window 1.5x wider checks
//      convergence: a localized multiplier must reappear in it within window_tolerance.
//   2. certification: each localized eigenvector (little weight on the window's outer margin) embedded
//      in the full N-site ring, its residual ||M v - lambda v|| / ||v|| by one or two monodromy-vector
//      products on the full lattice (monodromy_product.hpp). A multiplier is certified when residual
//      and window difference are within their tolerances; else it is kept with the reason.
// The trivial +1 multipliers (2, 4 in strain form; bright_floquet.hpp) form a Jordan block, so the
// eigenvalue solver splits them by ~sqrt(machine epsilon): they are identified (nearest +1), not certified.
#include <complex>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "lrchain/index.hpp"
#include "lrchain/sim/dark/contact_bonds.hpp"
#include "lrchain/sim/dark/floquet.hpp"
#include "lrchain/sim/dark/shooting.hpp"

namespace lrchain::sim::bright {

struct WindowedFloquetOptions {
  Index count = 20;                 // localized multipliers certified, largest modulus first
  double fraction = 1e-10;          // core: sites whose largest |position| exceeds fraction x peak
  Index margin = 12;                // sites added on each side of the core
  Index cap = 401;                  // the first window's sites at most (the second is 1.5x)
  double edge_weight = 1e-3;        // localized: norm on the outer margins <= edge_weight x norm
  double window_tolerance = 1e-8;   // |lambda(window 1) - lambda(window 2)| for convergence
  double residual_tolerance = 1e-8; // ||M v - lambda v|| / ||v|| on the full lattice
  double unit_tolerance = 1e-6;     // |lambda| > 1 + tol counts as unstable
  double trivial_tolerance = 1e-3;  // the trivial multipliers lie this close to +1
};

struct WindowedMultiplier {
  std::complex<double> lambda;           // the first window's value
  double window_difference = 0;          // to the nearest multiplier of the second window
  std::optional<double> residual;        // on the full lattice (nullopt: not computed, see reason)
  bool certified = false;
  std::string reason;                    // why not certified ("" when certified)
};

struct WindowedFloquet {
  Index center = 0;                                // window centre site on the full ring
  Index sites = 0, check_sites = 0;                // the two windows
  Index full_sites = 0;
  std::vector<WindowedMultiplier> localized;       // the `count` largest-modulus localized ones, descending
  Index localized_found = 0;                       // localized eigenvectors in the first window (besides trivial)
  std::vector<std::complex<double>> trivial;       // identified trivial +1 multipliers (first window)
  double max_extended_modulus = 0;                 // largest |lambda| of the window's extended (phonon) modes
  Index products = 0;                              // full-lattice monodromy-vector products
  std::optional<dark::FloquetResult> verdict;      // classify_multipliers of the certified ones (nullopt: reason)
  std::string verdict_reason;                      // why there is no verdict
  double window_seconds = 0, certify_seconds = 0;
};

// The lattice a window is built on: the job's model, parameters and contacts, as the full shooting.
struct WindowLattice {
  const lrchain_lattice_kernels* kernels = nullptr;
  std::vector<double> parameters;
  bool mean_flow = false;
  dark::ContactBonds contacts;
};

// The windowed, certified multipliers of the breather Z(0) = [z0, 0] (positions field-major) of
// `shooting` (a ring of full_sites sites) at omega_b.
WindowedFloquet windowed_floquet(const dark::DarkShooting& shooting, const WindowLattice& lattice,
                                 const Eigen::VectorXd& z0, double omega_b, const WindowedFloquetOptions& options = {});

}  // namespace lrchain::sim::bright

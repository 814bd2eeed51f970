#pragma once
// Bright breathers of any model file: the NLS bright-breather ansatz built from the derived
// coefficients (omega, c, omega'', h_tilde, lambda), the lattice's own Bloch vector K and the
// derivation's second-order terms (second harmonic W2_f, mean W0_f, gradient term G_f per field):
//   u_f[n](t) = M1 tanh(z) + ((A K_f + G_f dA/dn) e^{i phi} + c.c.) + (A^2 W2_f e^{2 i phi} + c.c.) + |A|^2 W0_f,
// A = M2 sech(z), phi = n theta - omega_b t, z = a (n - n0 - c t), G_f the gradient term of A_{2,1,f}
// (-i dK_f/dtheta: the kernel of a wave packet's neighbouring wavenumbers; G_0 = 0),
// M2 = sqrt(2 (omega_b - omega) / h_tilde), a = sqrt(2 (omega - omega_b) / omega''), and the mean-flow
// kink M1 = lambda sqrt(2 omega'' (omega - omega_b)) / |h_tilde| of translation-invariant models
// (eq:focus_app with K = (1, kappa / (kappa - rho omega^2)) for the resonant chain, whose second
// harmonic is eq:A22A11 with B_{2,2} = kappa / (kappa - 4 rho omega^2) A_{2,2}; on-site models have no
// mean flow, M1 = 0, and a static offset W0 from their quadratic on-site force; in mean-flow models
// W0_0 = 0 and W0_f is field f's offset from the mean flow), run on the model's generated lattice
// (CompiledLattice) and compared with the ansatz field by field: E_f(t) = max_n |x_f - x_f^A| / max_n
// |x_f(0)|, where x_f is the strain u_f[n] - u_f[n-1] (translation-invariant models) or the
// displacement u_f[n] (on-site models).
#include <atomic>
#include <complex>
#include <cstddef>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "lrchain/model.hpp"
#include "lrchain/sim/integrator_options.hpp"
#include "lrchain/compiled_model_abi.h"
#include "lrchain/sim/model_lattice_bloch.hpp"
#include "lrchain/sim/run_record.hpp"

namespace lrchain::sim {

struct ModelBrightConfig {
  Index branch = 0;
  double theta = 0;
  std::optional<double> detuning;  // omega_b - omega; default sign(h_tilde) 1e-4
  double n0 = 0;
  Index N = 500;                   // sites n = -N..N (`sites` = 2N + 1 to the user: strain_sites.hpp)
  double periods = 200;            // run length in T_b
  double sample_every = 0.25;      // in T_b
  double steps_per_period = 0;     // srkn11b steps per period of the fastest linear mode (0: 24)
  double dt = 0;                   // srkn11b step (0: from steps_per_period)
  // Emitting ends (Sec. 4.2): the sites beyond both ends follow the ansatz instead of being fixed
  // (displacement form) or strain-free (strain form). The run is then driven, not autonomous:
  // integrated with rkf78 at `tolerance` (absolute and relative), and its energy is not conserved.
  bool ansatz_ends = false;
  double tolerance = 1e-10;
  // The O(eps^2) terms (second harmonic, mean offsets, gradient terms) in the ansatz; false: first order only
  // (eq:focus_app as printed).
  bool second_order = true;
  // Set (SIGINT): the run ends at its next step boundary (an observation time for the symplectic
  // stepper) with lrchain::Interrupted.
  const std::atomic<bool>* stop = nullptr;
  // Called at every sample with t / t_end in [0, 1] (a front end's progress display; empty: none).
  std::function<void(double fraction)> progress;
};

// The ansatz of one model, branch, theta and detuning.
class ModelBrightAnsatz {
 public:
  // Throws InvalidParameter("theta", ...) where the model's NLS is not focusing at theta (or is
  // singular there), InvalidParameter("detuning", ...) unless detuning * h_tilde > 0.
  // second_order: include the second harmonic and mean offsets (else they are zero).
  ModelBrightAnsatz(const Model& model, const lrchain_lattice_kernels& kernels, Index branch, double theta,
                    std::optional<double> detuning, double n0, bool second_order = true);
  const NlsCoefficients& nls() const { return nls_; }
  const BlochMode& mode() const { return mode_; }
  double omega_b() const { return omega_b_; }
  double period() const;
  double M1() const { return M1_; }
  double M2() const { return M2_; }
  double inverse_width() const { return a_; }
  // Per field: the second harmonic per unit A^2 and the mean per unit |A|^2 used (zero if not).
  const SecondOrderTerms& second_order() const { return second_order_; }
  bool uses_second_order() const { return uses_second_order_; }
  // Displacement and velocity of field f at site n, time t.
  void field(Index f, double n, double t, double& u, double& u_dot) const;

 private:
  NlsCoefficients nls_;
  BlochMode mode_;
  SecondOrderTerms second_order_;
  bool uses_second_order_ = false;
  double omega_b_ = 0, M1_ = 0, M2_ = 0, a_ = 0, n0_ = 0;
};

void validate(const ModelBrightConfig& c);

struct ModelBrightResult {
  double omega = 0, omega_b = 0, period = 0, group_velocity = 0, curvature = 0, h_tilde = 0, lambda = 0;
  double M1 = 0, M2 = 0, inverse_width = 0, dt = 0;  // dt: the srkn11b step (fixed ends)
  std::vector<std::complex<double>> kernel;        // Bloch vector K_f (K_0 = 1)
  SecondOrderTerms second_order;                   // W2_f, W0_f as used (zero when not)
  bool uses_second_order = false;
  bool ansatz_ends = false;               // emitting ends, integrated with rkf78
  double tolerance = 0;                   // rkf78's tolerance (ansatz ends)
  bool mean_flow = false;                 // strain form (translation-invariant) or displacement form
  std::vector<double> max_error;          // max_t E_f per field
  std::vector<double> final_error;
  double energy0 = 0, max_energy_drift = 0;
  std::optional<double> centre_speed;     // least-squares slope of the energy centre (null: no energy)
  // The largest share of the energy within end_zone_sites() of either fixed end, and the first time
  // it exceeded end_energy_limit with fixed or free ends: the breather (or its tails) reached an end
  // (null: never, no energy, or emitting ends).
  std::optional<double> max_end_energy_fraction;
  std::optional<double> end_reached_at;
  std::size_t end_zone = 0;  // the sites counted at each end (end_zone_sites)
  IntegrationStats stats;
  double solve_seconds = 0;
  RunRecord record;                       // series t, E_0.., energy, X; final snapshot
};

// The sites at each end whose energy share end_energy_limit bounds: 1/20 of the lattice, at least 2.
constexpr std::size_t end_zone_sites(std::size_t sites) { return sites / 20 > 2 ? sites / 20 : 2; }
// 1 % of the energy near an end: more than the breather's sech tails hold on a lattice many widths
// long, and more than the radiation a slowly drifting breather sheds over its run.
constexpr double end_energy_limit = 0.01;

ModelBrightResult run_bright(const Model& model, const lrchain_lattice_kernels& kernels,
                                   const ModelBrightConfig& c);

}  // namespace lrchain::sim

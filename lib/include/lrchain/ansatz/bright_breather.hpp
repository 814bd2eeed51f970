#pragma once
// Moving bright breather of the focusing NLS as initial data and reference for the lattice
// (Sec. 4.1): displacements u_n^A, v_n^A whose differences are eq:focus_app, and velocities whose
// differences are eq:focus_ini, with F = f = 0.
#include <optional>
#include <span>

#include "lrchain/coefficients.hpp"
#include "lrchain/dispersion.hpp"
#include "lrchain/index.hpp"
#include "lrchain/params.hpp"

namespace lrchain {

// Default detuning |omega_b - omega| of Sec. 4.1 (omega_b = omega + sign(h_tilde) 1e-4).
inline constexpr double kDefaultBrightDetuning = 1e-4;

class BrightBreatherAnsatz {
 public:
  // Breather on `branch` at carrier wavenumber theta, frequency omega_b = omega + detuning,
  // centred at n0. Default detuning: sign(h_tilde) * 1e-4 (Sec. 4.1).
  // Throws InvalidParameter("theta", ...) where the NLS is not focusing (omega'' h_tilde >= 0) or
  // its coefficients are singular, and InvalidParameter("detuning", ...) unless
  // detuning * h_tilde > 0 (then also detuning * omega'' < 0: sech solution eq:sechA exists).
  BrightBreatherAnsatz(const Params& p, Branch branch, double theta,
                       std::optional<double> detuning = std::nullopt, double n0 = 0.0);

  const Params& params() const { return params_; }
  Branch branch() const { return branch_; }
  const NlsCoefficients& nls() const { return nls_; }
  double theta() const { return nls_.theta; }
  double omega() const { return nls_.omega; }
  double omega_b() const { return omega_b_; }
  double period() const;                             // T_b = 2 pi / omega_b
  double group_velocity() const { return nls_.group_velocity; }
  double M1() const { return M1_; }                  // kink amplitude (eq:focus_app)
  double M2() const { return M2_; }                  // breather amplitude (eq:focus_app)
  double inverse_width() const { return a_; }        // a (eq:focus_app)
  double resonator_factor() const { return B_; }     // kappa / (kappa - rho omega^2) (eq:b10b11)
  double n0() const { return n0_; }

  // u_n^A(t) = M1 tanh(a(n-n0-ct)) + 2 M2 sech(a(n-n0-ct)) cos(n theta - omega_b t), and
  // v_n^A(t) with the oscillating part times kappa/(kappa - rho omega^2) (eq:ansatz_uv, eq:sechA11,
  // eq:sechA10, eq:b10b11); x = d^- u, y = d^- v are eq:focus_app.
  void displacements(double n, double t, double& u, double& v) const;
  // Time derivatives of the above; their differences are eq:focus_ini at t = 0.
  void velocities(double n, double t, double& u_dot, double& v_dot) const;
  // Strains x_n = u_n - u_{n-1}, y_n = v_n - v_{n-1} (eq:focus_app) for n = n_first .. n_first +
  // x.size() - 1 into x and y (of one size; std::invalid_argument otherwise).
  void strains(Index n_first, double t, std::span<double> x, std::span<double> y) const;

 private:
  Params params_;
  Branch branch_;
  NlsCoefficients nls_;
  double omega_b_ = 0, M1_ = 0, M2_ = 0, a_ = 0, B_ = 0, n0_ = 0;
};

}  // namespace lrchain

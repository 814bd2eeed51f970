#pragma once
// NLS coefficients of the modulation equations (eq:mod1, eq:mod2, eq:NLS), evaluated with the
// C++ code emitted by lrchain-derive (lib/include/lrchain/generated/nls_coefficients.hpp).
#include <string_view>

#include "lrchain/dispersion.hpp"
#include "lrchain/params.hpp"

namespace lrchain {

// focusing: omega''*h_tilde < 0; defocusing: > 0; degenerate: = 0 (e.g. theta = 0 optical, where
// the NLS is linear, Sec. 4.2); singular: a non-resonance condition is violated (h_tilde has a pole).
enum class Regime { focusing, defocusing, degenerate, singular };
std::string_view to_string(Regime r);

// How a loaded model's coefficients were obtained (lrchain/coefficient_check.hpp): directly from the
// emitted expressions, by their limit at a removable singularity (0/0) of those expressions, or not
// at all (refused: c, omega'', gamma, beta, h, lambda, h_tilde are NaN; singular_reason() says why).
enum class CoefficientEvaluation : signed char { direct, limit, refused };

struct NlsCoefficients {
  double theta = 0;           // carrier wavenumber
  double omega = 0;           // carrier frequency omega_+-(theta) (eq:disp1d)
  double group_velocity = 0;  // c = omega'(theta) (eq:c)
  double curvature = 0;       // omega''(theta) (eq:ppOmega)
  double gamma = 0;           // (eq:gamma)
  double beta = 0;            // coupling to the mean flow (eq:ppOmega)
  double h = 0;               // cubic coefficient before mean-flow elimination (eq:h); NaN if singular
  double lambda = 0;          // mean-flow factor (eq:lambda); NaN if singular
  double h_tilde = 0;         // h - lambda beta (eq:h_tilde); NaN if singular
  double h_tilde_numerator = 0;  // h_tilde * nonresonance1 * nonresonance2: smooth across the poles
  double nonresonance1 = 0;   // (4w^2-4K2 sin^2 th-k)(k-4w^2 rho)+k^2 (eq:nonresonance1), != 0 required
  double nonresonance2 = 0;   // c^2(1+rho)-K2 (eq:nonresonance2), != 0 required
  Regime regime = Regime::singular;  // focusing iff curvature*h_tilde < 0
  CoefficientEvaluation evaluation = CoefficientEvaluation::direct;  // refused: singular, see singular_reason()
};

// Relative size below which a non-resonance value counts as violated (|value| <= tol * scale).
inline constexpr double kNonresonanceTolerance = 1e-12;

// All NLS coefficients for one branch at wavenumber theta in (-pi, pi].
// Throws InvalidParameter for invalid params/theta (including theta = 0 on the acoustic branch,
// the zero-frequency mode). Allocation-free; built on the generated evaluators.
NlsCoefficients coefficients(const Params& p, Branch b, double theta);

// Throws InvalidParameter("theta") unless theta is a wavenumber of the resonant chain's branch b:
// finite, in (-pi, pi], nonzero on the acoustic branch (the checks of coefficients() above).
void check_resonant_chain_wavenumber(Branch b, double theta);

// Same without validation, for hot loops over pre-validated parameters (K's precomputed).
NlsCoefficients coefficients_unchecked(const Params& p, const TaylorCoefficients& K, Branch b,
                                       double theta);

}  // namespace lrchain

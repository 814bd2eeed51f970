#pragma once
// Order-by-order solution of the multiple-scale expansion (Sec. 3.1 and Appendix A):
// eps E^1 -> dispersion relation and kernel of M (eq:M); eps^2 E^1 -> group velocity c (eq:c);
// eps^2 E^2 -> second harmonic and (eq:nonresonance1); eps^3 E^0 -> mean flow (eq:mod2), lambda,
// (eq:nonresonance2); eps^3 E^1 -> NLS (eq:mod1): omega'', beta, h; then h_tilde = h - lambda beta.
#include <ginac/ginac.h>

#include <string>
#include <vector>

#include "lrchain/derivation/jets.hpp"
#include "lrchain/derivation/model.hpp"

namespace lrchain::derivation {

// Every coefficient is a rational expression in D1 = 4 sin^2(theta/2), sigma = sin(theta), omega,
// the model parameters, and the named intermediates c (group velocity) and gamma where stated.
struct DerivedCoefficients {
  const LatticeDescription* model = nullptr;
  GiNaC::ex dispersion;                // det L_1(theta, omega) = 0: the linear dispersion relation
  std::vector<GiNaC::ex> kernel;       // right null vector of L_1, first entry 1 (eq:b10b11)
  std::vector<GiNaC::ex> left_kernel;  // left null vector of L_1, first entry 1 (W* up to scale)
  GiNaC::ex group_velocity;            // c, from the eps^2 E^1 solvability condition
  GiNaC::ex gamma;                     // 1/(omega l.P.r): -2i / (coefficient of d_tau A_{1,1})
  GiNaC::ex curvature_over_gamma;      // omega''/gamma, contains the symbol c
  GiNaC::ex beta_over_gamma;           // beta/gamma
  GiNaC::ex nonresonance1;             // -det L_2 (second harmonic operator)
  GiNaC::ex h_n1_over_gamma;           // h * nonresonance1 / gamma (smooth in theta)
  GiNaC::ex nonresonance2;             // coefficient of d_xi^2 A_{1,0} in the mean-flow equation
  GiNaC::ex lambda_n2;                 // lambda * nonresonance2 (smooth)
  // Assembled (contain the symbols c and gamma where noted above, substituted here):
  GiNaC::ex curvature, beta, h, lambda, h_tilde, h_tilde_numerator;  // fully explicit
  // Second-order terms of the expansion per field f (fully explicit): the second harmonic
  // A_{2,2,f} / A_{1,1}^2 (complex in general) and the mean A_{2,0,f} / |A_{1,1}|^2. On-site models:
  // every field's static offset. Translation-invariant models: field 0's is 0 (its mean is the mean
  // flow A_{1,0}, with d_xi A_{1,0} = lambda |A_{1,1}|^2) and field f's is its offset from it, the
  // d_xi A_{1,0} part of A_{2,0,f} included through lambda.
  std::vector<GiNaC::ex> second_harmonic, mean_offset;
  // The envelope-gradient term of A_{2,1,f} = K_f A_{2,1} + kernel_gradient_f d_xi A_{1,1} per field
  // (0 for field 0; = -i dK_f/dtheta along the branch): a wave packet's kernel varies with its wavenumbers.
  std::vector<GiNaC::ex> kernel_gradient;
  std::vector<std::string> report;     // the derivation's own consistency checks, one line each
  std::vector<GiNaC::ex> vanishing_modulo_dispersion;  // coefficients that must be 0 on det L_1 = 0
  // Translation-invariant model (singular L_0): mean flow A_{1,0}, lambda, h_tilde = h - lambda beta.
  // Otherwise on-site (regular L_0): A_{1,0} = 0, A_{2,0} solved directly, beta = lambda = 0,
  // nonresonance2 = 1, h_tilde = h.
  bool mean_flow = true;
  // coefficient - conj(coefficient) where normal() alone does not give 0 (complex kernels): zero
  // only modulo sigma^2 = D1 - D1^2/4; checked by run_model_checks (every coefficient is real).
  std::vector<GiNaC::ex> imaginary_parts;
};

// left_kernel_scale multiplies every left null vector (a check: the coefficients must not change).
DerivedCoefficients derive(const LatticeDescription& model, const Symbols& s, const GiNaC::ex& left_kernel_scale = 1);

// Substitutes the group velocity and gamma into an expression containing the symbols c, gamma.
GiNaC::ex explicit_form(const DerivedCoefficients& d, const Symbols& s, const GiNaC::ex& e);

}  // namespace lrchain::derivation

#pragma once
// The check of a loaded model's NLS coefficients against omega itself: c = omega' and omega''
// from det M = 0 alone (Richardson-extrapolated central differences of the branch's omega^2 in
// theta), independent of the emitted expressions for c, omega'', h. Where the emitted expressions
// are 0/0 or lose their digits (a removable singularity, e.g. omega^2 = k3/m3 of a resonator),
// coefficients() evaluates them by their limit (h, lambda, h_tilde NaN with the regime singular
// where they have a pole, e.g. where the carrier has no amplitude in the first field); what fails
// both is refused as singular. coefficients() and coefficients_from_evaluators() run the full
// check; coefficients_at() (regime maps, scans) checks, without a second evaluation of the emitted
// NLS expressions, c and omega'' against det M's implicit derivatives (three evaluations of det M)
// and h_tilde against its numerator over the non-resonance values (two emitted forms that round
// independently, so they disagree where h's expressions lose digits to a 0/0), and runs the full
// check only where either fails.
#include <string_view>

#include "lrchain/coefficients.hpp"
#include "lrchain/index.hpp"

namespace lrchain {

struct ModelDefinition;

// omega's first and second derivative in theta along one branch of det M = 0, with error estimates
// (the change between two Richardson levels plus the rounding of the differences).
struct BranchDerivatives {
  double group_velocity = 0, group_velocity_error = 0;  // c = omega'
  double curvature = 0, curvature_error = 0;            // omega''
};

// Derivatives of omega on `branch` at theta (omega = that branch's frequency there) from the model's
// det M evaluator only; false where the branch has no positive omega^2 at a nearby wavenumber.
bool branch_derivatives(const ModelDefinition& definition, const double* q, Index branch, double theta, double omega,
                        BranchDerivatives& out) noexcept;

// The same derivatives at theta by the implicit function theorem on det M at fixed omega^2 (its
// central differences in theta at step 1e-4, no root of det M solved): three det M evaluations, the
// hot path's check (coefficients_at); false where they are not finite (e.g. omega = 0).
bool implicit_derivatives(const ModelDefinition& definition, const double* q, double theta, double omega,
                          BranchDerivatives& out) noexcept;

// True when c and omega'' of `c` agree with `d` (tolerance: 1e-7 relative to |c| + omega, resp.
// |omega''| + |c| + omega, plus ten times the estimated error of the differences).
bool agrees_with_derivatives(const NlsCoefficients& c, const BranchDerivatives& d) noexcept;

// Why `c` is singular (its regime is Regime::singular), or empty: a violated non-resonance
// condition (a pole of h), a pole of h found by the limit, or a removable singularity whose limit
// could not be evaluated (refused).
std::string_view singular_reason(const NlsCoefficients& c);

}  // namespace lrchain

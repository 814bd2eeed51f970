// The resonant chain's NLS coefficients over a contiguous array of wavenumbers, structure of arrays
// out. Blocks of kBlock wavenumbers: first sin and cos of theta/2 (half_angle.hpp, the same
// function as coefficients_unchecked), then the straight-line kernel (coefficients_kernel.hpp) over
// the block; the compiler vectorises both loops. Built for AVX-512, AVX2 and baseline x86-64, the
// variant chosen at load time by the CPU (target_clones). Only correctly rounded operations and selects
// are vectorised, so every variant is bit-identical to the scalar path.
#include "lrchain/coefficients_batch.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "coefficients_kernel.hpp"
#include "lrchain/half_angle.hpp"
#include "lrchain/model.hpp"

namespace lrchain {

namespace {

constexpr std::ptrdiff_t kBlock = 256;  // sin/cos scratch on the stack: 4 KiB

// x86-64 builds carry an AVX-512 and an AVX2 variant besides the baseline one.
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
#define LRCHAIN_VECTOR_VARIANTS __attribute__((target_clones("avx512f", "avx2", "default"), flatten))
#else
#define LRCHAIN_VECTOR_VARIANTS __attribute__((flatten))
#endif

// Coefficients of wavenumbers [start, start + count) from their half-angle sines and cosines.
// Parameters by value and restrict pointers: nothing the loop stores can alias what it reads.
template <Branch branch>
[[gnu::always_inline]] inline void evaluate_block(const Params p, const TaylorCoefficients K,
                                                  const double* __restrict theta, const double* __restrict sh,
                                                  const double* __restrict ch, std::ptrdiff_t count,
                                                  double* __restrict omega, double* __restrict group_velocity,
                                                  double* __restrict curvature, double* __restrict gamma,
                                                  double* __restrict beta, double* __restrict h,
                                                  double* __restrict lambda, double* __restrict h_tilde,
                                                  double* __restrict nonresonance1, double* __restrict nonresonance2,
                                                  std::int8_t* __restrict regime) {
  for (std::ptrdiff_t i = 0; i < count; ++i) {
    const NlsCoefficients c = detail::coefficients_from_half_angle<branch>(p, K, theta[i], sh[i], ch[i]);
    omega[i] = c.omega;
    group_velocity[i] = c.group_velocity;
    curvature[i] = c.curvature;
    gamma[i] = c.gamma;
    beta[i] = c.beta;
    h[i] = c.h;
    lambda[i] = c.lambda;
    h_tilde[i] = c.h_tilde;
    nonresonance1[i] = c.nonresonance1;
    nonresonance2[i] = c.nonresonance2;
    regime[i] = static_cast<std::int8_t>(c.regime);
  }
}

template <Branch branch>
[[gnu::always_inline]] inline void evaluate_all(const Params& p, const TaylorCoefficients& K, const double* theta,
                                                std::ptrdiff_t n, const CoefficientColumns& out) {
  double sh[kBlock], ch[kBlock];
  for (std::ptrdiff_t start = 0; start < n; start += kBlock) {
    const std::ptrdiff_t count = std::min(kBlock, n - start);
    for (std::ptrdiff_t i = 0; i < count; ++i) detail::half_angle_sincos(0.5 * theta[start + i], sh[i], ch[i]);
    double* const* f = out.field;
    evaluate_block<branch>(p, K, theta + start, sh, ch, count, f[0] + start, f[1] + start, f[2] + start,
                           f[3] + start, f[4] + start, f[5] + start, f[6] + start, f[7] + start, f[8] + start,
                           f[9] + start, out.regime + start);
  }
}

LRCHAIN_VECTOR_VARIANTS void evaluate_optical(const Params& p, const TaylorCoefficients& K, const double* theta,
                                              std::ptrdiff_t n, const CoefficientColumns& out) {
  evaluate_all<Branch::optical>(p, K, theta, n, out);
}

LRCHAIN_VECTOR_VARIANTS void evaluate_acoustic(const Params& p, const TaylorCoefficients& K, const double* theta,
                                               std::ptrdiff_t n, const CoefficientColumns& out) {
  evaluate_all<Branch::acoustic>(p, K, theta, n, out);
}

// The chain's vectorised loop with K2, K3, K4 given (as coefficients(Params) computes them).
void resonant_chain_batch(const Params& p, const TaylorCoefficients& K, Branch b, const double* theta,
                          std::ptrdiff_t n, const CoefficientColumns& out) noexcept {
  if (b == Branch::optical) evaluate_optical(p, K, theta, n, out);
  else evaluate_acoustic(p, K, theta, n, out);
}

// Whether any theta is outside (-pi, pi] (NaN included) or, on the acoustic branch, zero: one
// branch-free pass the compiler vectorises.
bool refused_wavenumbers(const double* theta, std::ptrdiff_t n, bool acoustic) {
  int refused = 0;
  for (std::ptrdiff_t i = 0; i < n; ++i)
    refused |= int(!(theta[i] > -std::numbers::pi)) | int(!(theta[i] <= std::numbers::pi)) | int(acoustic && theta[i] == 0.0);
  return refused != 0;
}

}  // namespace

void resonant_chain_coefficients_batch(const Params& p, Branch b, std::span<const double> theta,
                                       const CoefficientColumns& out) noexcept {
  resonant_chain_batch(p, taylor_coefficients(p), b, theta.data(), static_cast<std::ptrdiff_t>(theta.size()), out);
}

void coefficients_batch(const Model& model, Index branch, std::span<const double> theta, const CoefficientColumns& out,
                        std::ptrdiff_t* refused) {
  const std::ptrdiff_t n = static_cast<std::ptrdiff_t>(theta.size());
  const std::optional<Params>& p = model.resonant_chain_params();
  std::ptrdiff_t i = 0;
  try {
    if (!p || branch < 0 || branch >= static_cast<Index>(model.definition().branch_names.size())) {
      for (; i < n; ++i) out.store(i, coefficients(model, branch, theta[i]));  // refuses a bad branch
      return;
    }
    const Branch b = model.resonant_chain_branch(branch);
    if (refused_wavenumbers(theta.data(), n, b == Branch::acoustic))
      for (; i < n; ++i) coefficients(model, branch, theta[i]);  // throws the message of the first it refuses
  } catch (...) {
    if (refused) *refused = i;
    throw;
  }
  resonant_chain_batch(*p, model.resonant_chain_taylor_coefficients(), model.resonant_chain_branch(branch), theta.data(), n, out);
}

}  // namespace lrchain

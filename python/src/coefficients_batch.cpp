// The resonant chain's NLS coefficients over a contiguous array of wavenumbers, structure of arrays
// out. Blocks of kBlock wavenumbers: first sin and cos of theta/2 (half_angle.hpp, the same
// function as coefficients_unchecked), then the straight-line kernel (coefficients_kernel.hpp) over
// the block; the compiler vectorises both loops. Built for AVX-512, AVX2 and baseline x86-64, the
// variant chosen at load time by the CPU (target_clones). Only correctly rounded operations and selects
// are vectorised, so every variant is bit-identical to the scalar path.
#include "coefficients_batch.hpp"
#include "lrchain/coefficients_kernel.hpp"
#include "lrchain/half_angle.hpp"

#include <algorithm>
#include <cmath>

namespace lrchain::python {

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
[[gnu::always_inline]] inline void evaluate_all(const Params& p, const double* theta, std::ptrdiff_t n,
                                                const CoefficientColumns& out) {
  const TaylorCoefficients K = taylor_coefficients(p);
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

LRCHAIN_VECTOR_VARIANTS void evaluate_optical(const Params& p, const double* theta, std::ptrdiff_t n,
                                              const CoefficientColumns& out) {
  evaluate_all<Branch::optical>(p, theta, n, out);
}

LRCHAIN_VECTOR_VARIANTS void evaluate_acoustic(const Params& p, const double* theta, std::ptrdiff_t n,
                                               const CoefficientColumns& out) {
  evaluate_all<Branch::acoustic>(p, theta, n, out);
}

}  // namespace

void evaluate_resonant_chain(const Params& p, Branch b, const double* theta, std::ptrdiff_t n,
                             const CoefficientColumns& out) {
  if (b == Branch::optical) evaluate_optical(p, theta, n, out);
  else evaluate_acoustic(p, theta, n, out);
}

}  // namespace lrchain::python

// Vectorised stage update of the symplectic RKN steppers (contiguous_algebra.hpp).
#include "lrchain/sim/contiguous_algebra.hpp"

#include "vector_loops.hpp"

namespace lrchain::sim {

namespace {

// The three aliasing cases each as a restrict loop, so that GCC vectorises without runtime checks.
LRCHAIN_VECTOR_CLONES
void update_in_place_first(double* __restrict out, const double* __restrict y, double a1, double a2,
                           std::size_t n) {
  for (std::size_t i = 0; i < n; ++i) out[i] = a1 * out[i] + a2 * y[i];
}

// a1 = 1 (every RKN drift and kick): 1 * out[i] is out[i] exactly, so the same bits.
LRCHAIN_VECTOR_CLONES
void add_scaled_in_place(double* __restrict out, const double* __restrict y, double a2,
                         std::size_t n) {
  for (std::size_t i = 0; i < n; ++i) out[i] = out[i] + a2 * y[i];
}

LRCHAIN_VECTOR_CLONES
void update_in_place_second(double* __restrict out, const double* __restrict x, double a1,
                            double a2, std::size_t n) {
  for (std::size_t i = 0; i < n; ++i) out[i] = a1 * x[i] + a2 * out[i];
}

LRCHAIN_VECTOR_CLONES
void update_separate(double* __restrict out, const double* __restrict x, const double* __restrict y,
                     double a1, double a2, std::size_t n) {
  for (std::size_t i = 0; i < n; ++i) out[i] = a1 * x[i] + a2 * y[i];
}

}  // namespace

void scale_sum2_contiguous(double* out, const double* x, const double* y, double a1, double a2,
                           std::size_t n) {
  if (out == x && a1 == 1.0 && a2 == 0.0) return;  // x + 0*y: a zero drift/kick stage of the RKN
                                                   // steppers (equal to x for finite y)
  if (out == x && out == y) {
    for (std::size_t i = 0; i < n; ++i) out[i] = a1 * out[i] + a2 * out[i];
  } else if (out == x && a1 == 1.0) {
    add_scaled_in_place(out, y, a2, n);
  } else if (out == x) {
    update_in_place_first(out, y, a1, a2, n);
  } else if (out == y) {
    update_in_place_second(out, x, a1, a2, n);
  } else {
    update_separate(out, x, y, a1, a2, n);
  }
}

}  // namespace lrchain::sim

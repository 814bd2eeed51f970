#pragma once
// A Boost.Odeint algebra for std::vector<double, Allocator> states (any allocator, e.g. the
// cache-line aligned one of integrate_observed's RKN steppers): the stage update of the symplectic RKN
// steppers, out = a1 x + a2 y (Odeint's scale_sum2), runs as one vectorised loop over contiguous
// storage (AVX-512 / AVX2 / SSE2 chosen at run time); every other operation is Odeint's
// range_algebra. Same IEEE operations as range_algebra + default_operations, so same results.
#include <cstddef>
#include <type_traits>
#include <vector>

#include <boost/numeric/odeint/algebra/default_operations.hpp>
#include <boost/numeric/odeint/algebra/range_algebra.hpp>

namespace lrchain::sim {

// out[i] = a1 * x[i] + a2 * y[i] for i < n; out may be x or y (element-wise update).
void scale_sum2_contiguous(double* out, const double* x, const double* y, double a1, double a2,
                           std::size_t n);

namespace detail {
template <class S>
struct is_double_vector : std::false_type {};
template <class A>
struct is_double_vector<std::vector<double, A>> : std::true_type {};
}  // namespace detail

// A std::vector<double> with any allocator (contiguous storage).
template <class S>
concept contiguous_doubles = detail::is_double_vector<std::remove_const_t<S>>::value;

struct contiguous_algebra : boost::numeric::odeint::range_algebra {
  using boost::numeric::odeint::range_algebra::for_each3;

  template <contiguous_doubles S1, contiguous_doubles S2, contiguous_doubles S3>
  static void for_each3(S1& s1, S2& s2, S3& s3,
                        boost::numeric::odeint::default_operations::scale_sum2<double, double> op) {
    scale_sum2_contiguous(s1.data(), s2.data(), s3.data(), op.m_alpha1, op.m_alpha2, s1.size());
  }
};

}  // namespace lrchain::sim

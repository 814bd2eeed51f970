// Second harmonic and mean of the multiple-scale expansion of a loaded model (model.hpp,
// second_order_terms): the emitted harmonics evaluator at the branch's omega.
#include <cmath>

#include "lrchain/half_angle.hpp"
#include "lrchain/model.hpp"

namespace lrchain {

// A_{2,2,f} / A_{1,1}^2, A_{2,0,f} / |A_{1,1}|^2 and G_f per field at (branch, theta).
SecondOrderTerms second_order_terms(const Model& model, Index branch, double theta) {
  const NlsCoefficients c = coefficients_from_evaluators(model, branch, theta);  // checks theta, branch; gives omega
  const ModelDefinition& d = model.definition();
  double sh, ch;
  detail::half_angle_sincos(0.5 * theta, sh, ch);
  double out[harmonic_output_count * kMaxModelDegree];
  d.evaluators.evaluate_harmonics(4.0 * sh * sh, 2.0 * sh * ch, c.omega, model.inputs().data(), out);
  SecondOrderTerms terms;
  for (int f = 0; f < d.degree; ++f) {
    const double* field = out + harmonic_output_count * f;
    terms.second_harmonic.emplace_back(field[harmonic_second_real], field[harmonic_second_imaginary]);
    terms.mean.push_back(field[harmonic_mean]);
    terms.kernel_gradient.emplace_back(field[harmonic_gradient_real], field[harmonic_gradient_imaginary]);
  }
  return terms;
}

}  // namespace lrchain

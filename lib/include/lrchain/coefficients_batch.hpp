#pragma once
// NLS coefficients (eq:c, eq:ppOmega, eq:gamma, eq:h, eq:lambda, eq:h_tilde) over a contiguous array
// of wavenumbers into columns (structure of arrays): the resonant chain's vectorised loop, and any
// loaded model through coefficients(). Serves C++ callers, the coeffs job and the Python module.
#include <cstddef>
#include <cstdint>
#include <span>

#include "lrchain/coefficients.hpp"
#include "lrchain/index.hpp"

namespace lrchain {

class Model;

// Names of the coefficient columns, in CoefficientColumns::field order.
inline constexpr int kCoefficientColumnCount = 10;
inline constexpr const char* kCoefficientColumnNames[kCoefficientColumnCount] = {
    "omega", "group_velocity", "curvature", "gamma", "beta", "h", "lambda", "h_tilde", "nonresonance1", "nonresonance2"};

// Output columns, each as long as the wavenumbers evaluated: the coefficients in kCoefficientColumnNames order and the Regime codes.
struct CoefficientColumns {
  double* field[kCoefficientColumnCount];
  std::int8_t* regime;

  // Stores c at index i.
  void store(std::ptrdiff_t i, const NlsCoefficients& c) const noexcept {
    field[0][i] = c.omega;
    field[1][i] = c.group_velocity;
    field[2][i] = c.curvature;
    field[3][i] = c.gamma;
    field[4][i] = c.beta;
    field[5][i] = c.h;
    field[6][i] = c.lambda;
    field[7][i] = c.h_tilde;
    field[8][i] = c.nonresonance1;
    field[9][i] = c.nonresonance2;
    regime[i] = static_cast<std::int8_t>(c.regime);
  }
};

// The resonant chain's coefficients at every theta into out (theta.size() values per column),
// without checks: p valid, each theta in (-pi, pi] and nonzero on the acoustic branch. One
// vectorised loop (AVX-512, AVX2 or baseline x86-64, chosen at load time), bit-identical to
// coefficients(p, b, theta[i]). Allocation-free.
void resonant_chain_coefficients_batch(const Params& p, Branch b, std::span<const double> theta,
                                       const CoefficientColumns& out) noexcept;

// coefficients(model, branch, theta[i]) for every i, bit for bit, into out: the resonant chain
// (Model::resonant_chain_params) through the vectorised loop above after checking every theta,
// other models one evaluation per wavenumber. Throws what coefficients() throws for the first
// wavenumber it refuses (out then holds no complete result), after storing its index in *refused
// when `refused` is given.
void coefficients_batch(const Model& model, Index branch, std::span<const double> theta, const CoefficientColumns& out,
                        std::ptrdiff_t* refused = nullptr);

}  // namespace lrchain

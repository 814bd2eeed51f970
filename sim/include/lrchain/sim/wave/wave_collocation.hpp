#pragma once
// The collocation form of a periodic travelling wave u_f[n](t) = U_f(theta n - omega t) of a model
// lattice (docs/waves.md): U_f sampled at the 2H+1 phases xi_j = 2 pi j / (2H+1), trigonometric
// interpolation between them, and the model's forces at every phase read from its generated kernels
// on a short fixed-end chain whose sites hold U(xi_j + m theta) (m = -R..R, the lattice shifts exact
// on the Fourier modes: e^{i k m theta}).
#include <complex>
#include <vector>

#include <Eigen/Dense>

#include "lrchain/index.hpp"
#include "lrchain/sim/model_lattice.hpp"
#include "lrchain/compiled_model_abi.h"

namespace lrchain::sim::wave {

// Spectral matrices on the 2H+1 equispaced phases of [0, 2 pi): d/dxi, d^2/dxi^2 and the shift
// U(xi) -> U(xi + s) (exact on the harmonics |k| <= H).
struct CollocationGrid {
  explicit CollocationGrid(Index harmonics);
  Index harmonics = 0, points = 0;
  Eigen::MatrixXd first_derivative, second_derivative;
  // The real matrix of the shift by s (its entries (1 + 2 sum_k cos(k (xi_j - xi_l + s))) / N).
  Eigen::MatrixXd shift(double s) const;
  double phase(Index j) const;
};

// Complex harmonics c_k (k = 0..H) of samples at the grid's phases: U(xi) = sum_{|k|<=H} c_k e^{i k xi}.
std::vector<std::complex<double>> harmonics_of(const double* samples, Index points);
// Samples at the 2 harmonics_new + 1 phases of the trigonometric interpolant of `samples` (more or fewer harmonics).
std::vector<double> resampled(const double* samples, Index points, Index harmonics_new);

// The model's lattice seen by a travelling wave of wavenumber theta: its accelerations and their
// Jacobian blocks J_m = d a_n / d u_{n+m} at every collocation phase, for the stencil shifts m the
// kernels use. Not thread-safe (scratch buffers; nothing allocates per phase).
class WaveLattice {
 public:
  WaveLattice(const lrchain_lattice_kernels& kernels, std::vector<double> parameters, double theta);
  Index fields() const { return fields_; }
  double theta() const { return theta_; }
  const std::vector<int>& shifts() const { return shifts_; }  // stencil shifts m with a nonzero block somewhere
  // The uniform displacement of every field is a symmetry (a translation-invariant model).
  bool translation_invariant() const { return translation_invariant_; }
  const lrchain_lattice_kernels& kernels() const { return chain_.kernels(); }
  const std::vector<double>& parameters() const { return parameters_; }

  // Shifted profiles of `profile` (fields x points, field-major) for every stencil shift: the chain states.
  void prepare(const CollocationGrid& grid, const Eigen::VectorXd& profile);
  // Accelerations a_f(xi_j) (field-major, fields x points) of the prepared profile.
  void accelerations(Eigen::VectorXd& a);
  // blocks[s](g + fields * f, j): d a_g(xi_j) / d u_f[n + shifts()[s]] at the prepared profile.
  void jacobian_blocks(std::vector<Eigen::MatrixXd>& blocks);
  // The least contact overlap over the prepared profile and every one-sided bond (+inf: none).
  double least_contact_overlap(Index& bond) const;
  // The shift matrix U(xi) -> U(xi + m theta) on the prepared grid, |m| <= 7.
  const Eigen::MatrixXd& shift_matrix(int m) const { return shift_matrices_[std::size_t(m + radius_)]; }

 private:
  void load_chain(Index j);
  std::vector<double> parameters_;
  double theta_;
  Index fields_, radius_, sites_;
  CompiledLattice chain_;
  std::vector<int> shifts_;
  bool translation_invariant_ = false;
  Index points_ = 0;
  std::vector<Eigen::MatrixXd> shift_matrices_;  // per offset -radius..radius on the prepared grid
  std::vector<Eigen::VectorXd> shifted_;  // per stencil offset -radius..radius: S_m U (fields x points)
  std::vector<double> q_, a_, dq_, da_;
};

}  // namespace lrchain::sim::wave

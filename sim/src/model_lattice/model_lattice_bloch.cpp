// Linear Bloch modes of a model lattice from its Jacobian at rest (model_lattice_bloch.hpp).
#include "lrchain/sim/model_lattice_bloch.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <numeric>

#include <fmt/format.h>

#include "lrchain/errors.hpp"
#include "lrchain/sim/model_lattice.hpp"

namespace lrchain::sim {

namespace {

// D(theta)_{gf} = sum_m d_{gf,m} e^{i m theta} from the Jacobian at rest applied to cos(n theta)
// and sin(n theta) on one field, read at a middle site n0 of a fixed-end chain (shifts are <= 3):
// (J cos)_g[n0] + i (J sin)_g[n0] = e^{i n0 theta} D_{gf}. Then D K = -omega^2 K. The
// eigen-decomposition, with its eigenvalue order by increasing omega^2.
struct BlochProblem {
  Eigen::ComplexEigenSolver<Eigen::MatrixXcd> solver;
  std::vector<std::size_t> order;
  double scale = 0;
};

BlochProblem bloch_problem(const lrchain_lattice_kernels& kernels, const std::vector<double>& parameters, double theta) {
  constexpr std::size_t sites = 16, n0 = 8;
  const CompiledLattice chain(kernels, parameters, sites, false, LatticeForm::displacement);
  const std::size_t fields = chain.fields(), size = chain.positions();
  const std::vector<double> rest(size, 0.0);
  std::vector<double> pattern(size), response_cos(size), response_sin(size);
  Eigen::MatrixXcd D(fields, fields);
  const std::complex<double> back = std::polar(1.0, -theta * double(n0));
  for (std::size_t f = 0; f < fields; ++f) {
    std::fill(pattern.begin(), pattern.end(), 0.0);
    for (std::size_t n = 0; n < sites; ++n) pattern[f * sites + n] = std::cos(theta * double(n));
    chain.jacobian_action(rest.data(), pattern.data(), response_cos.data());
    for (std::size_t n = 0; n < sites; ++n) pattern[f * sites + n] = std::sin(theta * double(n));
    chain.jacobian_action(rest.data(), pattern.data(), response_sin.data());
    for (std::size_t g = 0; g < fields; ++g)
      D(Eigen::Index(g), Eigen::Index(f)) =
          back * std::complex<double>(response_cos[g * sites + n0], response_sin[g * sites + n0]);
  }
  BlochProblem p;
  p.solver.compute(D);
  p.order.resize(fields);
  std::iota(p.order.begin(), p.order.end(), 0);
  const auto omega2 = [&](std::size_t i) { return -p.solver.eigenvalues()(Eigen::Index(i)).real(); };
  std::sort(p.order.begin(), p.order.end(), [&](std::size_t a, std::size_t b) { return omega2(a) < omega2(b); });
  p.scale = D.cwiseAbs().maxCoeff();
  return p;
}

// omega of eigenvalue i, or InvalidParameter("theta") where it is not real and positive.
double branch_frequency(const lrchain_lattice_kernels& kernels, const BlochProblem& p, std::size_t i, double theta) {
  const std::complex<double> lambda = p.solver.eigenvalues()(Eigen::Index(i));
  if (!(-lambda.real() > 1e-12 * p.scale) || std::abs(lambda.imag()) > 1e-9 * p.scale)
    throw InvalidParameter("theta", fmt::format("{}: a branch has no real positive frequency at theta = {} "
                                                "(omega^2 = {})", kernels.model_name, theta, -lambda.real()));
  return std::sqrt(-lambda.real());
}

}  // namespace

std::vector<double> branch_frequencies(const lrchain_lattice_kernels& kernels, const std::vector<double>& parameters,
                                       double theta) {
  const BlochProblem p = bloch_problem(kernels, parameters, theta);
  std::vector<double> omegas;
  for (std::size_t i : p.order) omegas.push_back(branch_frequency(kernels, p, i, theta));
  return omegas;
}

std::array<double, 2> branch_band(const lrchain_lattice_kernels& kernels, const std::vector<double>& parameters,
                                  Index branch, Index samples) {
  std::array<double, 2> band{std::numeric_limits<double>::infinity(), 0.0};
  for (Index k = 0; k <= samples; ++k) {
    const BlochProblem p = bloch_problem(kernels, parameters, std::numbers::pi * double(k) / double(samples));
    const double omega2 = -p.solver.eigenvalues()(Eigen::Index(p.order.at(std::size_t(branch)))).real();
    const double omega = std::sqrt(std::max(0.0, omega2));
    band = {std::min(band[0], omega), std::max(band[1], omega)};
  }
  return band;
}

std::vector<BlochMode> bloch_modes(const lrchain_lattice_kernels& kernels, const std::vector<double>& parameters,
                                   double theta) {
  const BlochProblem p = bloch_problem(kernels, parameters, theta);
  std::vector<BlochMode> modes;
  for (std::size_t i : p.order) {
    BlochMode mode;
    mode.omega = branch_frequency(kernels, p, i, theta);
    const auto v = p.solver.eigenvectors().col(Eigen::Index(i));
    if (std::abs(v(0)) > 1e-10 * v.cwiseAbs().maxCoeff())  // else the first field is at rest: no kernel
      for (Eigen::Index f = 0; f < v.size(); ++f) mode.kernel.push_back(v(f) / v(0));
    modes.push_back(std::move(mode));
  }
  return modes;
}

std::vector<double> lattice_parameters(const Model& model) {
  const std::size_t count = model.definition().parameters.size();
  return {model.inputs().begin(), model.inputs().begin() + std::ptrdiff_t(count)};
}

const lrchain_lattice_kernels* compiled_in_lattice_kernels(const Model& model) {
  const lrchain_lattice_kernels* kernels = shipped_lattice_kernels(model.name());
  const ModelDefinition* shipped = find_shipped_model(model.name());
  return kernels && shipped && shipped->file_sha256 == model.definition().file_sha256 ? kernels : nullptr;
}

const lrchain_lattice_kernels& lattice_kernels_of(const Model& model) {
  const lrchain_lattice_kernels* kernels = compiled_in_lattice_kernels(model);
  if (!kernels)
    throw InputError("--model: no compiled-in lattice code for model '" + model.name() +
                     "': it is not one of the shipped model files (models/*.toml); a user's model file has its "
                     "lattice code compiled at run time (lrchain simulate --model FILE)");
  return *kernels;
}

BlochMode bloch_mode(const Model& model, const lrchain_lattice_kernels& kernels, Index branch, double theta) {
  const std::vector<BlochMode> modes = bloch_modes(kernels, lattice_parameters(model), theta);
  if (branch < 0 || branch >= static_cast<Index>(modes.size()))
    throw InvalidParameter("branch", fmt::format("{} has {} branches", model.name(), modes.size()));
  const NlsCoefficients nls = coefficients_from_evaluators(model, branch, theta);
  if (!(std::abs(modes[branch].omega - nls.omega) <= 1e-9 * nls.omega))
    throw NumericalFailure(fmt::format("{}: the lattice code gives omega = {:.12g} at theta = {}, the coefficient "
                                       "evaluators {:.12g}; they do not describe the same lattice",
                                       model.name(), modes[branch].omega, theta, nls.omega));
  if (modes[branch].kernel.empty())
    throw InvalidParameter("theta", fmt::format("{}: the first field is at rest in the Bloch mode of branch {} at theta = "
                                                "{}, so the NLS amplitude is undefined there; choose another theta",
                                                model.name(), model.definition().branch_names[std::size_t(branch)], theta));
  return modes[branch];
}

}  // namespace lrchain::sim

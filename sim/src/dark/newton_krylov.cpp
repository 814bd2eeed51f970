// Newton-Krylov on the reversible shooting: Jacobian-vector products from one tangent replayed on the
// orbit's recorded steps, GMRES preconditioned by the band-probed Jacobian (newton_krylov.hpp).
#include "lrchain/sim/dark/newton_krylov.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <vector>

#include <Eigen/Sparse>
#include <Eigen/SparseLU>
#include <unsupported/Eigen/IterativeSolvers>

#include "lrchain/errors.hpp"
#include "lrchain/sim/dark/shooting.hpp"

namespace lrchain::sim::dark {
class ShootingJacobianOperator;
}

// Eigen's matrix-free operator protocol (the "matrixfree_cg" example of Eigen's documentation): the
// operator is a sparse-like EigenBase whose product with a vector is evaluated by scaleAndAddTo.
namespace Eigen::internal {
template <>
struct traits<lrchain::sim::dark::ShootingJacobianOperator> : public traits<SparseMatrix<double>> {};
}  // namespace Eigen::internal

namespace lrchain::sim::dark {

// The square system's Jacobian J v at the linearization point (the orbit's recorded steps from [q, 0]):
// rows are Zdot(T_b/2) of the tangent started at [v, 0], with, for strain-form models, row 0 replaced
// by the C_x row 0.5 (v_0 + dZ_0(T_b/2)).
class ShootingJacobianOperator : public Eigen::EigenBase<ShootingJacobianOperator> {
 public:
  using Scalar = double;
  using RealScalar = double;
  using StorageIndex = int;
  enum { ColsAtCompileTime = Eigen::Dynamic, MaxColsAtCompileTime = Eigen::Dynamic, IsRowMajor = false };

  ShootingJacobianOperator(const DarkShooting& shooting, const DarkOrbit::RecordedSteps& steps, bool mean_flow)
      : orbit_(shooting.orbit()), steps_(steps), mean_flow_(mean_flow),
        positions_(shooting.orbit().positions()), extended_(std::size_t(4 * positions_), 0.0) {}
  Eigen::Index rows() const { return positions_; }
  Eigen::Index cols() const { return positions_; }
  void set_point(const Eigen::VectorXd& q) { q_ = &q; }

  template <typename Rhs>
  Eigen::Product<ShootingJacobianOperator, Rhs, Eigen::AliasFreeProduct> operator*(const Eigen::MatrixBase<Rhs>& x) const {
    return Eigen::Product<ShootingJacobianOperator, Rhs, Eigen::AliasFreeProduct>(*this, x.derived());
  }

  // out += alpha J v (one tangent replayed with the orbit over the recorded half period).
  template <typename Dest, typename Rhs>
  void add_product(Dest& out, const Rhs& v, double alpha) const {
    const std::size_t P = std::size_t(positions_), n = 2 * P;
    std::fill(extended_.begin(), extended_.end(), 0.0);
    for (std::size_t i = 0; i < P; ++i) {
      extended_[i] = (*q_)(Eigen::Index(i));
      extended_[n + i] = v(Eigen::Index(i));
    }
    orbit_.replay(steps_, extended_, 1);
    ++products;
    for (std::size_t i = 0; i < P; ++i) out(Eigen::Index(i)) += alpha * extended_[n + P + i];
    if (mean_flow_) out(0) += alpha * (0.5 * (v(0) + extended_[n]) - extended_[n + P]);
  }
  mutable Index products = 0;

 private:
  const DarkOrbit& orbit_;
  const DarkOrbit::RecordedSteps& steps_;
  bool mean_flow_;
  Eigen::Index positions_;
  const Eigen::VectorXd* q_ = nullptr;
  mutable std::vector<double> extended_;
};

// The band-probed Jacobian's sparse LU as Eigen's preconditioner protocol (compute is a no-op on the
// operator: the factorization is set by factorize).
class BandPreconditioner {
 public:
  BandPreconditioner() = default;
  template <typename M>
  BandPreconditioner& analyzePattern(const M&) { return *this; }
  template <typename M>
  BandPreconditioner& factorize(const M&) { return *this; }
  template <typename M>
  BandPreconditioner& compute(const M&) { return *this; }
  void set(const Eigen::SparseMatrix<double>& jacobian) {
    lu_.compute(jacobian);
    if (lu_.info() != Eigen::Success) throw NumericalFailure("Newton-Krylov: the band-probed Jacobian is singular");
  }
  template <typename Rhs>
  Eigen::VectorXd solve(const Eigen::MatrixBase<Rhs>& b) const { return lu_.solve(b); }
  Eigen::ComputationInfo info() const { return Eigen::Success; }

 private:
  Eigen::SparseLU<Eigen::SparseMatrix<double>, Eigen::COLAMDOrdering<int>> lu_;
};

}  // namespace lrchain::sim::dark

namespace Eigen::internal {
template <typename Rhs>
struct generic_product_impl<lrchain::sim::dark::ShootingJacobianOperator, Rhs, SparseShape, DenseShape, GemvProduct>
    : generic_product_impl_base<lrchain::sim::dark::ShootingJacobianOperator, Rhs,
                                generic_product_impl<lrchain::sim::dark::ShootingJacobianOperator, Rhs>> {
  using Scalar = typename Product<lrchain::sim::dark::ShootingJacobianOperator, Rhs>::Scalar;
  template <typename Dest>
  static void scaleAndAddTo(Dest& dst, const lrchain::sim::dark::ShootingJacobianOperator& lhs, const Rhs& rhs,
                            const Scalar& alpha) {
    lhs.add_product(dst, rhs, alpha);
  }
};
}  // namespace Eigen::internal

namespace lrchain::sim::dark {

namespace {

// Probe colours of the sites: sites of one colour are more than 2 band apart on the ring (full blocks
// of 2 band + 1 sites coloured n mod (2 band + 1), the remainder one colour each); every site its own
// colour when the ring is too short for that.
std::vector<Index> probe_colours(Index sites, Index band, Index& colours) {
  const Index width = 2 * band + 1;
  std::vector<Index> colour(std::size_t(sites), 0);
  if (sites < 2 * width) {
    for (Index n = 0; n < sites; ++n) colour[std::size_t(n)] = n;
    colours = sites;
    return colour;
  }
  const Index full = (sites / width) * width;
  for (Index n = 0; n < sites; ++n) colour[std::size_t(n)] = n < full ? n % width : width + (n - full);
  colours = width + (sites - full);
  return colour;
}

// The square system's Jacobian within the band (all of it on short rings) from fields x colours
// tangents replayed in batches on the recorded steps: entry (row (f, m), column (g, n)) read from the
// probe of (g, colour(n)) for |m - n| <= band on the ring.
Eigen::SparseMatrix<double> probe_band_jacobian(const DarkShooting& shooting, const DarkOrbit::RecordedSteps& steps,
                                                const Eigen::VectorXd& q, bool mean_flow, Index band,
                                                Index& probe_columns) {
  const DarkOrbit& orbit = shooting.orbit();
  const Index N = orbit.sites(), P = orbit.positions(), F = P / N, n2 = 2 * P;
  Index colours = 0;
  const std::vector<Index> colour = probe_colours(N, band, colours);
  const bool dense = colours == N;
  std::vector<std::vector<Index>> members(static_cast<std::size_t>(colours));
  for (Index n = 0; n < N; ++n) members[std::size_t(colour[std::size_t(n)])].push_back(n);
  const Index total = F * colours;
  probe_columns = total;
  constexpr Index batch = 16;  // tangents integrated together (the stepper's 13 stages stay small)
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(std::size_t(P) * std::size_t(F) * std::size_t(dense ? N : 2 * band + 1));
  std::vector<double> extended;
  for (Index first = 0; first < total; first += batch) {
    const Index m = std::min(batch, total - first);
    extended.assign(std::size_t(n2 * (1 + m)), 0.0);
    for (Index i = 0; i < P; ++i) extended[std::size_t(i)] = q(i);
    for (Index j = 0; j < m; ++j) {
      const Index g = (first + j) / colours, c = (first + j) % colours;
      for (Index n : members[std::size_t(c)]) extended[std::size_t(n2 * (1 + j) + g * N + n)] = 1.0;
    }
    orbit.replay(steps, extended, m);
    for (Index j = 0; j < m; ++j) {
      const Index g = (first + j) / colours, c = (first + j) % colours;
      const double* tangent = extended.data() + n2 * (1 + j);
      for (Index n : members[std::size_t(c)]) {
        const Index column = g * N + n;
        const Index reach = dense ? N : 2 * band + 1;
        for (Index d = 0; d < reach; ++d) {
          const Index site = dense ? d : (n - band + d + N) % N;
          for (Index f = 0; f < F; ++f) {
            const Index row = f * N + site;
            const double value = mean_flow && row == 0 ? 0.5 * (tangent[0] + (column == 0 ? 1.0 : 0.0))
                                                       : tangent[P + row];
            if (value != 0.0) entries.emplace_back(int(row), int(column), value);
          }
        }
      }
    }
  }
  Eigen::SparseMatrix<double> J(P, P);
  J.setFromTriplets(entries.begin(), entries.end());
  return J;
}

}  // namespace

NewtonResult newton_krylov_solve(const DarkShooting& shooting, Eigen::VectorXd q0, double omega_b,
                                 const NewtonKrylovOptions& options, NewtonKrylovStats* stats) {
  if (shooting.mode() != ShootingMode::reversible)
    throw std::invalid_argument("newton_krylov_solve: needs the reversible shooting");
  if (options.band < 1) throw InvalidParameter("krylov_band", "must be >= 1, got " + std::to_string(options.band));
  NewtonKrylovStats local;
  NewtonKrylovStats& s = stats ? *stats : local;
  const DarkOrbit& orbit = shooting.orbit();
  const Index P = orbit.positions();
  const bool mean_flow = shooting.mean_flow();
  const double half_period = std::numbers::pi / omega_b;
  DarkOrbit::RecordedSteps steps;
  std::vector<double> state(std::size_t(2 * P), 0.0);
  Eigen::VectorXd point;  // the linearization point q of `steps`
  ShootingJacobianOperator jacobian(shooting, steps, mean_flow);
  Eigen::GMRES<ShootingJacobianOperator, BandPreconditioner> gmres;
  gmres.setTolerance(options.gmres_tolerance);
  gmres.setMaxIterations(options.gmres_max_iterations);
  gmres.set_restart(int(options.gmres_restart));
  bool probe = true;
  Eigen::VectorXd square(P);
  auto linearize = [&](const Eigen::VectorXd& q, Eigen::VectorXd& r) {
    point = q;
    std::fill(state.begin(), state.end(), 0.0);
    std::copy(q.data(), q.data() + P, state.begin());
    const double x0 = q(0);
    orbit.record(state, 0.0, half_period, steps);
    r.resize(P + (mean_flow ? 1 : 0));
    for (Index i = 0; i < P; ++i) r(i) = state[std::size_t(P + i)];
    if (mean_flow) r(P) = 0.5 * (x0 + state[0]);  // eq:center at the far site, as DarkShooting::evaluate
  };
  auto step = [&](const Eigen::VectorXd&, const Eigen::VectorXd& r) -> Eigen::VectorXd {
    square = r.head(P);
    if (mean_flow) square(0) = r(P);
    jacobian.set_point(point);
    if (probe) {
      gmres.preconditioner().set(probe_band_jacobian(shooting, steps, point, mean_flow, options.band, s.probe_columns));
      ++s.preconditioner_builds;
      probe = false;
    }
    gmres.compute(jacobian);
    const Index before = jacobian.products;
    Eigen::VectorXd dq = gmres.solve(-square);
    s.gmres_iterations.push_back(Index(gmres.iterations()));
    s.jacobian_products += jacobian.products - before;
    if (gmres.iterations() > options.max_preconditioned_iterations) probe = true;
    return dq;
  };
  return newton_iterate(shooting, std::move(q0), options.newton, linearize, step);
}

}  // namespace lrchain::sim::dark

// The reflection symmetry of a dark breather of a model lattice (lattice_reflection.hpp).
#include "lrchain/sim/dark/lattice_reflection.hpp"

#include <cmath>
#include <random>

#include <fmt/format.h>

namespace lrchain::sim::dark {

Eigen::VectorXd reflect(const LatticeReflection& r, const Eigen::VectorXd& z) {
  Eigen::VectorXd out(z.size());
  for (Eigen::Index p = 0; p < z.size(); ++p) out(r.image[std::size_t(p)]) = r.sign[std::size_t(p)] * z(p);
  return out;
}

namespace {
// Columns e_p + parity sign_p e_image(p) (normalised), one per orbit {p, image(p)} that has one.
Eigen::MatrixXd reflection_basis(const LatticeReflection& r, double parity) {
  const Eigen::Index P = Eigen::Index(r.image.size());
  std::vector<Eigen::VectorXd> columns;
  for (Eigen::Index p = 0; p < P; ++p) {
    const Eigen::Index q = r.image[std::size_t(p)];
    const double s = parity * r.sign[std::size_t(p)];
    if (q < p) continue;
    Eigen::VectorXd v = Eigen::VectorXd::Zero(P);
    if (q == p) {
      if (s < 0) continue;  // a fixed position with sign -parity is zero in this subspace
      v(p) = 1.0;
    } else {
      v(p) = M_SQRT1_2;
      v(q) = s * M_SQRT1_2;
    }
    columns.push_back(std::move(v));
  }
  Eigen::MatrixXd B(P, Eigen::Index(columns.size()));
  for (std::size_t j = 0; j < columns.size(); ++j) B.col(Eigen::Index(j)) = columns[j];
  return B;
}

// The field-f candidates: (offset o, sign s) with R_f seed_f = target_f.
struct FieldMap {
  Index offset;
  double sign;
};

Index wrap(Index i, Index n) { return ((i % n) + n) % n; }
}  // namespace

Eigen::MatrixXd reflection_even_basis(const LatticeReflection& r) { return reflection_basis(r, 1.0); }
Eigen::MatrixXd reflection_odd_basis(const LatticeReflection& r) { return reflection_basis(r, -1.0); }

std::optional<LatticeReflection> find_dark_reflection(const CompiledLattice& lattice, double centre,
                                                      const Eigen::VectorXd& seed,
                                                      const Eigen::VectorXd& seed_half_period, double tolerance) {
  const Index N = lattice.sites(), F = lattice.fields(), P = lattice.positions();
  const Index K = Index(std::lround(2.0 * centre));
  const double scale = seed.cwiseAbs().maxCoeff();
  if (!(scale > 0) || seed.size() != P || seed_half_period.size() != P) return std::nullopt;
  for (const bool half : {false, true}) {
    const Eigen::VectorXd& target = half ? seed_half_period : seed;
    // Each field's maps that carry the seed onto the target (field by field: the seed is separable).
    std::vector<std::vector<FieldMap>> per_field(static_cast<std::size_t>(F));
    for (Index f = 0; f < F; ++f)
      for (const Index o : {Index(0), Index(1)})
        for (const double s : {1.0, -1.0}) {
          double worst = 0;
          for (Index i = 0; i < N; ++i) {
            const Index j = wrap(K + o - i, N);
            // The seed's first strain r[0] = u[0] - u[-1] is the infinite lattice's, not the ring's.
            if (i == 0 || j == 0) continue;
            worst = std::max(worst, std::abs(s * seed(f * N + i) - target(f * N + j)));
          }
          if (worst <= tolerance * scale) per_field[std::size_t(f)].push_back({o, s});
        }
    // Every combination of the fields' maps (usually one), kept if it commutes with the accelerations.
    std::vector<std::size_t> choice(std::size_t(F), 0);
    bool empty = false;
    for (const auto& options : per_field) empty = empty || options.empty();
    if (empty) continue;
    for (;;) {
      LatticeReflection r;
      r.half_period = half;
      r.image.resize(std::size_t(P));
      r.sign.resize(std::size_t(P));
      std::string maps;
      for (Index f = 0; f < F; ++f) {
        const FieldMap m = per_field[std::size_t(f)][choice[std::size_t(f)]];
        for (Index i = 0; i < N; ++i) {
          r.image[std::size_t(f * N + i)] = f * N + wrap(K + m.offset - i, N);
          r.sign[std::size_t(f * N + i)] = m.sign;
        }
        maps += fmt::format("{}i -> ({} - i) mod {} with sign {}", f == 0 ? "" : "; ", K + m.offset, N,
                            m.sign > 0 ? "+" : "-");
      }
      r.description = maps + (half ? ", after half a period" : ", at all times");
      // R a(z) = a(R z) at two random states of the seed's size around it (a fixed seed: reproducible).
      std::mt19937_64 random(20261128);
      std::uniform_real_distribution<double> uniform(-1.0, 1.0);
      bool commutes = true;
      std::vector<double> a(static_cast<std::size_t>(P)), a_reflected(static_cast<std::size_t>(P));
      for (int trial = 0; trial < 2 && commutes; ++trial) {
        Eigen::VectorXd z = seed;
        for (Eigen::Index p = 0; p < P; ++p) z(p) += scale * uniform(random);
        const Eigen::VectorXd rz = reflect(r, z);
        lattice.acceleration(z.data(), a.data());
        lattice.acceleration(rz.data(), a_reflected.data());
        const Eigen::VectorXd ra = reflect(r, Eigen::Map<const Eigen::VectorXd>(a.data(), P));
        const double size = ra.cwiseAbs().maxCoeff();
        const double defect = (ra - Eigen::Map<const Eigen::VectorXd>(a_reflected.data(), P)).cwiseAbs().maxCoeff();
        commutes = std::isfinite(size) && defect <= 1e-10 * size + 1e-300;
      }
      if (commutes) return r;
      Index f = 0;
      while (f < F && ++choice[std::size_t(f)] == per_field[std::size_t(f)].size()) choice[std::size_t(f++)] = 0;
      if (f == F) break;
    }
  }
  return std::nullopt;
}

}  // namespace lrchain::sim::dark

// lib chooses the resonant chain's specialised evaluators itself (Model::resonant_chain_params):
// coefficients() of the chain loaded as a generic Model equals coefficients(Params) bit for bit, and
// the batch loop (lrchain/coefficients_batch.hpp) equals the scalar path bit for bit. The expected
// values are the scalar coefficients(Params, Branch, theta) of lib/src/coefficients.cpp.
#include <doctest/doctest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <vector>

#include "lrchain/coefficients.hpp"
#include "lrchain/coefficients_batch.hpp"
#include "lrchain/errors.hpp"
#include "lrchain/model.hpp"

using namespace lrchain;

namespace {

// The ten output fields and the regime of two results are the same bits (NaN included).
bool same_bits(const NlsCoefficients& a, const NlsCoefficients& b) {
  const double x[] = {a.omega, a.group_velocity, a.curvature, a.gamma, a.beta, a.h, a.lambda, a.h_tilde,
                      a.nonresonance1, a.nonresonance2};
  const double y[] = {b.omega, b.group_velocity, b.curvature, b.gamma, b.beta, b.h, b.lambda, b.h_tilde,
                      b.nonresonance1, b.nonresonance2};
  for (int k = 0; k < 10; ++k)
    if (std::bit_cast<std::uint64_t>(x[k]) != std::bit_cast<std::uint64_t>(y[k])) return false;
  return a.regime == b.regime && std::bit_cast<std::uint64_t>(a.theta) == std::bit_cast<std::uint64_t>(b.theta);
}

Model chain_at(const Params& p) {
  return shipped_model("resonant_chain", {{"alpha", p.alpha}, {"delta0", p.delta0}, {"kappa", p.kappa}, {"rho", p.rho}});
}

// Wavenumbers over (-pi, pi], zero left out (the acoustic branch has no frequency there).
std::vector<double> wavenumbers(int n) {
  std::vector<double> theta;
  for (int i = 0; i < n; ++i) theta.push_back(-std::numbers::pi + 2 * std::numbers::pi * (i + 1) / n);
  for (double& t : theta)
    if (t == 0.0) t = 0.5;
  return theta;
}

// Columns over caller-owned storage of n values each.
struct Storage {
  std::vector<double> values[kCoefficientColumnCount];
  std::vector<std::int8_t> regime;
  CoefficientColumns columns{};
  explicit Storage(std::size_t n) : regime(n) {
    for (int k = 0; k < kCoefficientColumnCount; ++k) columns.field[k] = (values[k] = std::vector<double>(n)).data();
    columns.regime = regime.data();
  }
  NlsCoefficients at(std::size_t i, double theta) const {
    NlsCoefficients c;
    c.theta = theta;
    c.omega = values[0][i], c.group_velocity = values[1][i], c.curvature = values[2][i], c.gamma = values[3][i];
    c.beta = values[4][i], c.h = values[5][i], c.lambda = values[6][i], c.h_tilde = values[7][i];
    c.nonresonance1 = values[8][i], c.nonresonance2 = values[9][i];
    c.regime = static_cast<Regime>(regime[i]);
    return c;
  }
};

const Params kParams[] = {Params{}, Params{1.5, 0.3, 2.0, 0.1}, Params{2.5, 1.0, 0.5, 3.0}, Params{1.5, 4.0 / 9, 1, 10}};

}  // namespace

TEST_CASE("coefficients() of the resonant chain loaded as a Model takes the specialised path, bit for bit") {
  const std::vector<double> theta = wavenumbers(200);
  int generic_differs = 0;  // points where the model's own evaluators give other bits: the test can tell the paths apart
  for (const Params& p : kParams) {
    const Model m = chain_at(p);
    REQUIRE(m.resonant_chain_params().has_value());
    CHECK(m.resonant_chain_params()->rho == p.rho);
    for (const auto& [name, b] : {std::pair{"acoustic", Branch::acoustic}, std::pair{"optical", Branch::optical}}) {
      const Index branch = m.branch(name);
      CHECK(m.resonant_chain_branch(branch) == b);
      for (double t : theta) {
        INFO(name << " theta=" << t << " rho=" << p.rho);
        const NlsCoefficients fast = coefficients(p, b, t);
        CHECK(same_bits(coefficients(m, branch, t), fast));
        const NlsCoefficients generic = coefficients_from_evaluators(m, branch, t);
        generic_differs += !same_bits(generic, fast);
      }
    }
  }
  // The generic evaluator differs from the specialised one in the last bits at many points (it
  // agrees to 1e-10, model_api_test.cpp): before lib dispatched, coefficients(Model) returned it.
  CHECK(generic_differs > 100);
}

TEST_CASE("the chain's identity is its file's SHA-256, not its name") {
  const ModelDefinition& shipped = *find_shipped_model("resonant_chain");
  CHECK(shipped.is_resonant_chain());
  ModelDefinition copy = shipped;  // a definition loaded from a copy of the file
  CHECK(copy.is_resonant_chain());
  ModelDefinition renamed = *find_shipped_model("resonant_chain_polynomial");  // another file named like the chain
  renamed.name = "resonant_chain";
  CHECK(!renamed.is_resonant_chain());
  for (const char* name : {"fput", "klein_gordon", "resonant_chain_polynomial"}) {
    INFO(name);
    const Model m = shipped_model(name);
    CHECK(!m.resonant_chain_params().has_value());
    NlsCoefficients generic;
    REQUIRE(coefficients_at(m.definition(), m.inputs().data(), 0, 1.0, generic));
    CHECK(same_bits(coefficients(m, 0, 1.0), generic));  // other models: their own evaluators
  }
}

TEST_CASE("the chain as a Model refuses what coefficients(Params) refuses, with the Model API's messages") {
  const Model m = shipped_model("resonant_chain");
  const Index acoustic = m.branch("acoustic");
  CHECK_THROWS_WITH_AS(coefficients(m, acoustic, 0.0), doctest::Contains("has no positive frequency here"),
                       InvalidParameter);
  CHECK_THROWS_AS(coefficients(m, acoustic, 4.0), InvalidParameter);
  CHECK_THROWS_AS(coefficients(m, 2, 1.0), InvalidParameter);
}

TEST_CASE("the batch loop from C++ equals the scalar coefficients bit for bit") {
  const std::vector<double> theta = wavenumbers(1001);  // not a multiple of the loop's block of 256
  for (const Params& p : kParams)
    for (Branch b : {Branch::optical, Branch::acoustic}) {
      Storage out(theta.size());
      resonant_chain_coefficients_batch(p, b, theta, out.columns);
      int differing = 0;
      for (std::size_t i = 0; i < theta.size(); ++i) differing += !same_bits(out.at(i, theta[i]), coefficients(p, b, theta[i]));
      INFO(to_string(b) << " rho=" << p.rho);
      CHECK(differing == 0);
    }
}

TEST_CASE("coefficients_batch of a Model equals coefficients() per wavenumber, the chain's and other models'") {
  const std::vector<double> theta = wavenumbers(300);
  for (const char* name : {"resonant_chain", "fput", "klein_gordon", "diatomic_chain"}) {
    const Model m = shipped_model(name);
    for (Index branch = 0; branch < static_cast<Index>(m.definition().branch_names.size()); ++branch) {
      Storage out(theta.size());
      coefficients_batch(m, branch, theta, out.columns);
      int differing = 0;
      for (std::size_t i = 0; i < theta.size(); ++i) differing += !same_bits(out.at(i, theta[i]), coefficients(m, branch, theta[i]));
      INFO(name << " branch " << branch);
      CHECK(differing == 0);
    }
  }
  // A wavenumber the scalar path refuses is refused here too.
  const Model chain = shipped_model("resonant_chain");
  const std::vector<double> with_zero = {1.0, 0.0};
  Storage out(with_zero.size());
  CHECK_THROWS_WITH_AS(coefficients_batch(chain, chain.branch("acoustic"), with_zero, out.columns),
                       doctest::Contains("has no positive frequency here"), InvalidParameter);
  CHECK_THROWS_AS(coefficients_batch(shipped_model("fput"), 0, with_zero, out.columns), InvalidParameter);
  // The index of the first refused wavenumber (the position Python's messages name).
  const auto refused_at = [&](const Model& m, Index branch, const std::vector<double>& theta) {
    std::ptrdiff_t refused = -1;
    Storage columns(theta.size());
    CHECK_THROWS_AS(coefficients_batch(m, branch, theta, columns.columns, &refused), InvalidParameter);
    return refused;
  };
  CHECK(refused_at(chain, chain.branch("acoustic"), {1.0, 2.0, 0.0, 0.0}) == 2);
  CHECK(refused_at(chain, chain.branch("optical"), {1.0, std::nan(""), 4.0}) == 1);
  CHECK(refused_at(chain, chain.branch("optical"), {1.0, 0.0, -4.0}) == 2);
  CHECK(refused_at(shipped_model("fput"), 0, {1.0, 0.5, 0.0}) == 2);
}

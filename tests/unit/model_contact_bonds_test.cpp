// The one-sided contacts that the generated lattice code exports (lrchain/compiled_model_abi.h, read by
// model_contact_bonds in contact_bonds.hpp) equal the overlaps an independent computation gives: a
// second parse of the model file's force text with GiNaC (the dark solver's former reader, run at
// these parameter values; its output is quoted below), in strain and displacement form. Smooth models
// export none. The exported overlap is the one the generated accelerations clamp: a bond's force
// stops responding to its neighbour exactly where the overlap is negative.
#include <doctest/doctest.h>

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "lrchain/sim/dark/contact_bonds.hpp"
#include "lrchain/sim/model_lattice.hpp"

namespace {

using lrchain::sim::dark::ContactBond;
using lrchain::sim::dark::ContactBonds;
using lrchain::sim::dark::ContactBondTerm;

const lrchain_lattice_kernels& kernels(const char* name) {
  const lrchain_lattice_kernels* k = lrchain::sim::shipped_lattice_kernels(name);
  REQUIRE(k != nullptr);
  return *k;
}

// Same bonds in the same order: offsets and coefficients to round-off, variables and shifts exactly.
void check_bonds(const ContactBonds& got, const std::vector<ContactBond>& expected) {
  REQUIRE(got.size() == expected.size());
  for (std::size_t j = 0; j < got.size(); ++j) {
    CAPTURE(expected[j].name);
    CHECK(got[j].name == expected[j].name);
    CHECK(got[j].offset == doctest::Approx(expected[j].offset).epsilon(1e-15));
    REQUIRE(got[j].terms.size() == expected[j].terms.size());
    for (std::size_t k = 0; k < got[j].terms.size(); ++k) {
      CHECK(got[j].terms[k].variable == expected[j].terms[k].variable);
      CHECK(got[j].terms[k].shift == expected[j].terms[k].shift);
      CHECK(got[j].terms[k].coefficient == doctest::Approx(expected[j].terms[k].coefficient).epsilon(1e-15));
    }
  }
}

}  // namespace

TEST_CASE("model contacts: the resonant chain's generated overlaps equal the force text's" * doctest::test_suite("fast")) {
  using lrchain::sim::dark::model_contact_bonds;
  const auto& k = kernels("resonant_chain");
  // Parameters alpha, delta0, kappa, rho (the file's order). The former reader at the defaults:
  //   strain:       F(u[n+1] - u[n]) offset 0.44444444444444442: (0,0,-1)
  //   displacement: F(u[n+1] - u[n]) offset 0.44444444444444442: (0,0,1) (0,1,-1)
  // and with delta0 = 0.3, strain: offset 0.29999999999999999: (0,0,-1).
  check_bonds(model_contact_bonds(k, {1.5, 4.0 / 9.0, 1.0, 1.0 / 3.0}, true),
              {{"F(u[n+1] - u[n])", 0.44444444444444442, {{0, 0, -1.0}}}});
  check_bonds(model_contact_bonds(k, {1.5, 4.0 / 9.0, 1.0, 1.0 / 3.0}, false),
              {{"F(u[n+1] - u[n])", 0.44444444444444442, {{0, 0, 1.0}, {0, 1, -1.0}}}});
  check_bonds(model_contact_bonds(k, {1.5, 0.3, 1.0, 1.0 / 3.0}, true),
              {{"F(u[n+1] - u[n])", 0.29999999999999999, {{0, 0, -1.0}}}});
}

TEST_CASE("model contacts: the diatomic chain's two bonds equal the force text's" * doctest::test_suite("fast")) {
  using lrchain::sim::dark::model_contact_bonds;
  const auto& k = kernels("diatomic_chain");
  // Parameters alpha, delta0, m. The former reader named the bonds by their first call in the force
  // text, F(v[n] - u[n]) and F(u[n] - v[n-1]); the generated names shift each to its lowest site n.
  //   strain (defaults):        offset 0.44444444444444442: (1,0,-1) | (0,1,-1) (1,0,1)
  //   displacement (delta0 0.7): offset 0.69999999999999996: (0,0,1) (1,0,-1) | (0,1,-1) (1,0,1)
  check_bonds(model_contact_bonds(k, {1.5, 4.0 / 9.0, 2.0}, true),
              {{"F(v[n] - u[n])", 0.44444444444444442, {{1, 0, -1.0}}},
               {"F(u[n+1] - v[n])", 0.44444444444444442, {{0, 1, -1.0}, {1, 0, 1.0}}}});
  check_bonds(model_contact_bonds(k, {1.5, 0.7, 2.0}, false),
              {{"F(v[n] - u[n])", 0.69999999999999996, {{0, 0, 1.0}, {1, 0, -1.0}}},
               {"F(u[n+1] - v[n])", 0.69999999999999996, {{0, 1, -1.0}, {1, 0, 1.0}}}});
}

TEST_CASE("model contacts: smooth models export none and a wrong parameter count is refused" * doctest::test_suite("fast")) {
  using lrchain::sim::dark::model_contact_bonds;
  for (const char* smooth : {"fput", "klein_gordon", "resonant_chain_polynomial"}) {
    CAPTURE(smooth);
    const auto& k = kernels(smooth);
    CHECK(k.displacement_contacts == nullptr);
    CHECK(k.strain_contacts == nullptr);
    CHECK(model_contact_bonds(k, std::vector<double>(std::size_t(k.parameter_count), 0.5), false).empty());
  }
  const auto& cradle = kernels("newtons_cradle");  // on-site: contacts in displacement form only
  CHECK(cradle.displacement_contacts != nullptr);
  CHECK(cradle.strain_contacts == nullptr);
  CHECK_THROWS_AS(model_contact_bonds(kernels("resonant_chain"), {1.5, 0.3}, true), std::invalid_argument);
}

TEST_CASE("model contacts: the generated accelerations drop a bond's force exactly where its overlap is negative" *
          doctest::test_suite("fast")) {
  // The resonant chain on a periodic ring of 12 sites, beads displaced so that some Hertz bonds open
  // (overlap < 0) and others close. Bond n (overlap s_n from the exported table) joins beads n and
  // n+1; in displacement form d a_u[n] / d u[n+1] = F'(u[n+1] - u[n]), in strain form
  // d a_r[n+1] / d r[n] = F'(r[n]) (r'' = a_u[n] - a_u[n-1]): alpha s_n^(alpha-1) > 0 while the beads
  // touch, exactly 0 once the contact is lost.
  using namespace lrchain::sim;
  using lrchain::sim::dark::contact_overlaps;
  using lrchain::sim::dark::model_contact_bonds;
  const auto& k = kernels("resonant_chain");
  const std::vector<double> p{1.5, 4.0 / 9.0, 1.0, 1.0 / 3.0};
  const int N = 12;
  const double pattern[4] = {0.0, 0.6, -0.05, 0.1};  // first variable (u or r): both signs of s_n
  for (const bool strain : {false, true}) {
    CAPTURE(strain);
    const CompiledLattice lattice(k, p, std::size_t(N), true, strain ? LatticeForm::strain : LatticeForm::displacement);
    const auto bonds = model_contact_bonds(k, p, strain);
    REQUIRE(bonds.size() == 1);
    std::vector<double> q(2 * std::size_t(N), 0.0), zero(q.size(), 0.0), s(q.size() / 2, 0.0), rate(q.size() / 2, 0.0);
    for (int n = 0; n < N; ++n) q[std::size_t(n)] = pattern[n % 4];
    contact_overlaps(bonds, N, q.data(), zero.data(), s.data(), rate.data());
    int open = 0, closed = 0;
    for (int n = 0; n < N; ++n) {
      CAPTURE(n);
      std::vector<double> dq(q.size(), 0.0), da(q.size(), 0.0);
      const int moved = strain ? n : (n + 1) % N, felt = strain ? (n + 1) % N : n;
      dq[std::size_t(moved)] = 1.0;
      lattice.jacobian_action(q.data(), dq.data(), da.data());
      const double response = da[std::size_t(felt)];
      if (s[std::size_t(n)] < 0) {
        CHECK(response == 0.0);
        ++open;
      } else {
        CHECK(response == doctest::Approx(1.5 * std::sqrt(s[std::size_t(n)])).epsilon(1e-12));
        ++closed;
      }
    }
    CHECK(open > 0);
    CHECK(closed > 0);
  }
}

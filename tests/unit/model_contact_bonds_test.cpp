// The one-sided contacts that the generated lattice code exports (model_lattice_abi.h, read by
// model_contact_bonds in contact_bonds.hpp) equal the overlaps an independent computation gives: a
// second parse of the model file's force text with GiNaC (the dark solver's former reader, run at
// these parameter values; its output is quoted below), in strain and displacement form. Smooth models
// export none.
#include <doctest/doctest.h>

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

// `lrchain dark floquet --model` on a two-field model whose breather opens contacts every period:
// the diatomic granular chain (defaults) at omega_b = 1.66 below its optical theta = 0 edge sqrt(3).
// Both of its Hertz bonds (bead u to the following bead v, v to the next u) are located; stepping
// across them instead, Newton stalls between 2e-9 and 1e-8 here (measured before contact changes were
// located on the model path).
#include <doctest/doctest.h>

#include <cstdio>
#include <string>

#include <nlohmann/json.hpp>

#include "../support/run_lrchain.hpp"

using lrchain::test::run_lrchain;

TEST_CASE("dark breathers of model files: diatomic_chain with contact changes every period (omega_b = 1.66)" *
          doctest::test_suite("validation")) {
  const auto r = run_lrchain({"dark", "floquet", "--model", "models/diatomic_chain.toml", "--omega-b", "1.66", "--sites",
                              "80", "--quiet", "--json"},
                             LRCHAIN_SOURCE_DIR);
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  const auto j = nlohmann::json::parse(r.out);
  const long changes = j["contact_changes_per_period"].get<long>();
  std::printf("dark diatomic_chain at omega_b 1.66, N 80: %d Newton iterations, E_b %.3e, %ld contact changes per "
              "period, Floquet %s max|lambda| %.6f pairing defect %.2e\n",
              j["newton_iterations"].get<int>(), j["measures"]["E_b"].get<double>(), changes,
              j["floquet"]["kind"].get<std::string>().c_str(), j["floquet"]["max_modulus"].get<double>(),
              j["floquet"]["pairing_defect"].get<double>());
  CHECK(j["one_sided_contacts"] == nlohmann::json::array({"F(v[n] - u[n])", "F(u[n+1] - v[n])"}));
  CHECK(j["contact_changes_located"] == true);
  CHECK(changes > 0);  // measured 304
  CHECK(changes % 2 == 0);
  CHECK(j["measures"]["E_b"].get<double>() <= 1e-10);  // the target; measured 4.6e-12
  // Hamiltonian pairing of the full-period monodromy's multipliers: measured 1.7e-7 (1e-4 allowed, as
  // for the model breathers that keep contact, dark_model_test.cpp).
  CHECK(j["floquet"]["pairing_defect"].get<double>() < 1e-4);
}

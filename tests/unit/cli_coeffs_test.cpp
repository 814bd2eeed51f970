// `lrchain coeffs` end to end (issue 2, section 4): JSON keys, full precision, exit codes.
#include <doctest/doctest.h>

#include <nlohmann/json.hpp>
#include <string>

#include "../support/run_lrchain.hpp"

namespace {
struct Run {
  int code;
  std::string out;
};
// `lrchain <words of args>`: exit code and stdout.
Run run(const std::string& args) {
  const auto r = lrchain::test::run_lrchain(lrchain::test::words(args));
  return {r.exit_code, r.out};
}
}  // namespace

TEST_CASE("coeffs --json prints every key with full precision") {
  const Run r = run("coeffs --theta pi/2 --rho 1/3 --branch optical --json");
  REQUIRE(r.code == 0);
  const auto j = nlohmann::json::parse(r.out);
  for (const char* key : {"omega", "group_velocity", "curvature", "gamma", "beta", "h", "lambda", "h_tilde",
                          "nonresonance1", "nonresonance2", "regime"})
    CHECK(j.contains(key));
  CHECK(j["regime"] == "focusing");
  CHECK(j["omega"].get<double>() - 1e-4 == doctest::Approx(2.1752).epsilon(3e-5));  // Fig. 6: omega_b = 2.1752
  CHECK(j["group_velocity"].get<double>() == doctest::Approx(0.23).epsilon(0.02));  // c_+ ~ 0.23 (Sec. 4.2)
}

TEST_CASE("coeffs at a non-resonance violation reports null and singular") {
  // theta where (eq:nonresonance1) vanishes on the acoustic branch at rho = 1/3 (root found to
  // full precision by the unit test 'regime and singular points'); pass it with 17 digits.
  const Run r = run("coeffs --theta 0 --branch optical --rho 1/3 --json");
  REQUIRE(r.code == 0);
  CHECK(nlohmann::json::parse(r.out)["regime"] == "degenerate");
}

TEST_CASE("bad input exits with code 2") {
  CHECK(run("coeffs --theta pi/2 --rho 0 --branch optical").code == 2);
  CHECK(run("coeffs --theta pi/2 --rho 1 --kappa -1 --branch optical").code == 2);
  CHECK(run("coeffs --theta pi/2 --rho 1 --delta0 0 --branch optical").code == 2);
  CHECK(run("coeffs --theta pi/2 --rho 1 --alpha 1 --branch optical").code == 2);
  CHECK(run("coeffs --theta 4 --rho 1 --branch optical").code == 2);
  CHECK(run("coeffs --theta nan --rho 1 --branch optical").code == 2);
  CHECK(run("coeffs --theta x --rho 1 --branch optical").code == 2);
  CHECK(run("coeffs --theta 1 --rho 1 --branch sideways").code == 2);
  CHECK(run("coeffs --rho 1 --branch optical").code == 2);
  CHECK(run("coeffs --table").code == 0);
}

// `lrchain coeffs` end to end (issue 2, section 4): JSON keys, full precision, exit codes.
#include <doctest/doctest.h>

#include <nlohmann/json.hpp>
#include <sstream>
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
  // The JSON echoes what was asked: branch, theta and the model's parameter values.
  CHECK(j["branch"] == "optical");
  CHECK(j["theta"].get<double>() == doctest::Approx(1.5707963267948966).epsilon(1e-15));
  CHECK(j["model"]["parameters"]["rho"].get<double>() == doctest::Approx(1.0 / 3).epsilon(1e-15));
  CHECK(j["model"]["parameters"]["delta0"].get<double>() == doctest::Approx(4.0 / 9).epsilon(1e-15));
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

TEST_CASE("coeffs --table: every column right-aligned under its header") {
  // Layout of print_table: theta in 7 characters, then 7 columns of a space and 12 characters.
  const Run r = run("coeffs --table --rho 1/3");
  REQUIRE(r.code == 0);
  std::istringstream lines(r.out);
  int checked = 0;
  for (std::string line; std::getline(lines, line);) {
    if (line.size() < 7 + 13 * 7 || line.find("branch") != std::string::npos || line.rfind("NLS", 0) == 0)
      continue;  // titles, blank lines
    INFO(line);
    for (int k = 1; k <= 7; ++k) {
      CHECK(line[7 + 13 * (k - 1)] == ' ');      // the separating space
      CHECK(line[7 + 13 * k - 1] != ' ');        // the column's last character: right-aligned
    }
    ++checked;
  }
  CHECK(checked == 2 * (1 + 6));  // two branches: header and six wavenumbers each
}

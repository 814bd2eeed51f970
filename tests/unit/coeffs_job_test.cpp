// The coefficients job (lrchain/jobs/coeffs.hpp) through the library: its checks name the Config
// key, one wavenumber and the table, and the JSON it gives the CLI.
#include <doctest/doctest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "lrchain/errors.hpp"
#include "lrchain/jobs/coeffs.hpp"

using namespace lrchain;

namespace {

// The optical frequency of the resonant chain from the dispersion relation (eq:disp1d), written out
// here: omega^2 = (S + sqrt(S^2 - 4 D kappa/rho))/2, S = D + kappa + kappa/rho, D = 4 K2 sin^2(theta/2),
// K2 = alpha delta0^(alpha - 1).
double optical_omega(const Params& p, double theta) {
  const double K2 = p.alpha * std::pow(p.delta0, p.alpha - 1);
  const double D = 4 * K2 * std::pow(std::sin(theta / 2), 2), S = D + p.kappa + p.kappa / p.rho;
  return std::sqrt((S + std::sqrt(S * S - 4 * D * p.kappa / p.rho)) / 2);
}

std::string key_of(const jobs::CoeffsConfig& config) {
  try {
    jobs::run_coeffs(config);
  } catch (const InvalidParameter& e) {
    return e.parameter();
  }
  return "";
}

}  // namespace

TEST_CASE("coeffs job: one wavenumber of the resonant chain, its branch spellings and the JSON") {
  jobs::CoeffsConfig config;
  config.params.rho = 3;
  config.branch = "opt";  // the chain's short spelling of optical
  config.theta = std::numbers::pi / 2;
  const jobs::CoeffsResult r = jobs::run_coeffs(config);
  CHECK(r.branch == "optical");
  CHECK(r.coefficients.omega == doctest::Approx(optical_omega(config.params, *config.theta)).epsilon(1e-14));
  CHECK(r.coefficients.omega == coefficients(config.params, Branch::optical, *config.theta).omega);  // the fast path's bits
  const nlohmann::json j = jobs::to_json(r);
  CHECK(j["branch"] == "optical");
  CHECK(j["model"]["name"] == "resonant_chain");
  CHECK(j["model"]["parameters"]["rho"] == 3.0);
  CHECK(j["omega"].get<double>() == r.coefficients.omega);
  CHECK(j.contains("provenance"));
}

TEST_CASE("coeffs job: checks name the Config key") {
  jobs::CoeffsConfig config;
  config.branch = "optical";
  CHECK(key_of(config) == "theta");  // required for one wavenumber
  config.theta = 4.0;
  CHECK(key_of(config) == "theta");  // outside (-pi, pi]
  config.theta = 1.0;
  config.branch = "";
  CHECK(key_of(config) == "branch");
  config.branch = "sideways";
  CHECK(key_of(config) == "branch");
  config.branch = "acoustic";
  config.theta = 0.0;
  CHECK(key_of(config) == "theta");  // the zero-frequency mode
  config.theta = 1.0;
  config.params.rho = -1;
  CHECK(key_of(config) == "rho");
  config.params.rho = 1;
  config.model = shipped_model("fput");
  config.branch = "optical";  // fput has one branch, 'acoustic'
  CHECK(key_of(config) == "branch");
}

TEST_CASE("coeffs job: the table of every branch, highest first, with lambda null for an on-site model") {
  jobs::CoeffsConfig config;
  config.table = true;
  const jobs::CoeffsResult chain = jobs::run_coeffs(config);
  REQUIRE(chain.table.size() == 2);
  CHECK(chain.table[0].name == "optical");
  REQUIRE(chain.table[0].rows.size() == jobs::table_thetas().size());
  // Row pi/2 of the optical branch: the dispersion relation written out above.
  CHECK(chain.table[0].rows[2].omega == doctest::Approx(optical_omega(Params{}, std::numbers::pi / 2)).epsilon(1e-14));
  const nlohmann::json j = jobs::to_json(chain);
  CHECK(j["branches"][1]["branch"] == "acoustic");
  CHECK(j["branches"][1]["rows"][5]["theta_label"] == "pi");

  config.model = shipped_model("klein_gordon", {{"C", 0.3}, {"w0", 1.2}});
  const nlohmann::json kg = jobs::to_json(jobs::run_coeffs(config));
  CHECK(kg["branches"].size() == 1);
  CHECK(kg["branches"][0]["rows"][0]["lambda"].is_null());
  // Klein-Gordon: omega^2 = w0^2 + 4 C sin^2(theta/2) (the textbook dispersion), at theta = pi.
  CHECK(kg["branches"][0]["rows"][5]["omega"].get<double>() == doctest::Approx(std::sqrt(1.44 + 1.2)).epsilon(1e-14));
}

TEST_CASE("coeffs job: without a branch, a model's only branch, and a model with several names them") {
  jobs::CoeffsConfig config;
  config.theta = 1.0;
  config.model = shipped_model("fput");  // one branch, 'acoustic'
  const jobs::CoeffsResult r = jobs::run_coeffs(config);
  CHECK(r.branch == "acoustic");
  // FPU: omega = 2 sin(theta/2) with unit mass and K2 = 1 (the textbook monatomic chain).
  CHECK(r.coefficients.omega == doctest::Approx(2 * std::sin(0.5)).epsilon(1e-14));
  config.model = shipped_model("diatomic_chain");
  try {
    jobs::run_coeffs(config);
    FAIL("a model with two branches needs --branch");
  } catch (const InvalidParameter& e) {
    CHECK(e.parameter() == "branch");
    CHECK(std::string(e.what()).find("'acoustic', 'optical'") != std::string::npos);
  }
}

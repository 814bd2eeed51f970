// `lrchain regime intervals|map|thresholds --model FILE`: the resonant chain's file gives the
// default (Params) path's intervals, and a model file written in a scratch directory goes through
// `regime map` with its regimes checked pixel by pixel against the hand-derived sign rule.
#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <numbers>
#include <sstream>
#include <string>
#include <unistd.h>

#include "../support/run_lrchain.hpp"

namespace fs = std::filesystem;
using lrchain::test::run_lrchain;

TEST_CASE("regime intervals --model models/resonant_chain.toml equals the default path") {
  const std::string file = std::string(LRCHAIN_SOURCE_DIR) + "/models/resonant_chain.toml";
  for (const char* rho : {"1/3", "3", "17.8"})
    for (const char* branch : {"optical", "acoustic"}) {
      INFO("rho " << rho << ", " << branch);
      const auto params = run_lrchain({"regime", "intervals", "--rho", rho, "--branch", branch});
      const auto model = run_lrchain({"regime", "intervals", "--model", file, "--set", std::string("rho=") + rho,
                                      "--branch", branch});
      REQUIRE(params.exit_code == 0);
      REQUIRE(model.exit_code == 0);
      const auto p = nlohmann::json::parse(params.out), m = nlohmann::json::parse(model.out);
      CHECK(m["model"]["name"] == "resonant_chain");
      CHECK(m["model"]["file_hash"] == p["model"]["file_hash"]);
      CHECK(m["model"]["parameters"] == p["model"]["parameters"]);
      REQUIRE(m["intervals"].size() == p["intervals"].size());
      for (std::size_t k = 0; k < p["intervals"].size(); ++k) {
        // Both end points are TOMS 748 brackets of width 1e-12 around the same zero.
        CHECK(std::abs(m["intervals"][k]["lo"].get<double>() - p["intervals"][k]["lo"].get<double>()) <= 2e-12);
        CHECK(std::abs(m["intervals"][k]["hi"].get<double>() - p["intervals"][k]["hi"].get<double>()) <= 2e-12);
        CHECK(m["intervals"][k]["lo_cause"] == p["intervals"][k]["lo_cause"]);
        CHECK(m["intervals"][k]["hi_cause"] == p["intervals"][k]["hi_cause"]);
      }
    }
}

TEST_CASE("a scratch model file goes through regime map, intervals and thresholds") {
  const fs::path dir = fs::temp_directory_path() / ("lrchain-user-model-regime-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir / "cache");
  {
    // Cubic on-site force only: omega^2 = w^2 + 4 K sin^2(theta/2) and the nonlinear frequency shift
    // is 3 g R^2 for u = 2R cos(theta n - omega t) (no second harmonic is driven), so by Lighthill's
    // criterion the wave is focusing iff omega'' g < 0, with omega'' of the sign of
    // w^2 cos(theta) - K (1 - cos(theta))^2 (see model_regime_test.cpp).
    std::ofstream f(dir / "quartic_chain.toml");
    f << "name = \"quartic_chain\"\n"
         "[parameters]\n"
         "K = { default = \"1/5\", range = \"(0, inf)\" }\n"
         "w = { default = 1, range = \"(0, inf)\" }\n"
         "g = { default = \"1/3\" }\n"
         "[[field]]\n"
         "name = \"u\"\n"
         "force = \"K*(u[n+1] - 2*u[n] + u[n-1]) - w^2*u[n] - g*u[n]^3\"\n";
  }
  const std::vector<std::string> env{"XDG_CACHE_HOME=" + (dir / "cache").string()};
  const std::string model = (dir / "quartic_chain.toml").string();
  const auto r = run_lrchain({"regime", "map", "--model", model, "--axis", "K", "--axis-range", "0.05", "2", "--nx",
                              "60", "--ny", "80", "--no-figures", "--out", (dir / "map").string()},
                             {}, env);
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  const auto j = nlohmann::json::parse(r.out);
  CHECK(j["plane"] == "theta-K");
  CHECK(j["model"]["name"] == "quartic_chain");
  CHECK(j["model"]["parameters"]["w"] == 1.0);
  CHECK(j["model"]["file_hash"].get<std::string>().size() == 18);
  REQUIRE(fs::exists(dir / "map" / "regime_theta-K_branch0.csv"));
  CHECK(fs::exists(dir / "map" / "boundary_theta-K_branch0_curvature_zero.csv"));
  std::ifstream csv(dir / "map" / "regime_theta-K_branch0.csv");
  std::string line;
  std::getline(csv, line);
  CHECK(line == "K,theta,regime");
  int pixels = 0, mismatched = 0, near_boundary = 0;
  while (std::getline(csv, line)) {
    if (line.empty()) continue;
    double K = 0, theta = 0;
    int regime = 0;
    char c1 = 0, c2 = 0;
    std::istringstream(line) >> K >> c1 >> theta >> c2 >> regime;
    ++pixels;
    const double curvature_sign = std::cos(theta) - K * std::pow(1 - std::cos(theta), 2);
    // The CSV holds 8 digits: pixels within 1e-6 of omega'' = 0 are not judged.
    if (std::abs(curvature_sign) < 1e-6) {
      ++near_boundary;
      continue;
    }
    mismatched += regime != (curvature_sign < 0 ? 1 : 0);  // g = 1/3 > 0
  }
  CHECK(pixels == 60 * 80);
  CHECK(mismatched == 0);
  MESSAGE("quartic_chain map: " << pixels << " pixels, " << near_boundary << " within 1e-6 of omega'' = 0");

  // intervals: the single focusing interval starts where omega'' = 0: cos(theta) = 1 + w^2/(2K) -
  // sqrt((1 + w^2/(2K))^2 - 1) (root of K x^2 - (2K + w^2) x + K = 0, x = cos(theta)).
  const auto iv = run_lrchain({"regime", "intervals", "--model", model, "--set", "K=0.5"}, {}, env);
  REQUIRE(iv.exit_code == 0);
  const auto ij = nlohmann::json::parse(iv.out);
  REQUIRE(ij["intervals"].size() == 1);
  const double x = 2.0 - std::sqrt(3.0);
  CHECK(std::abs(ij["intervals"][0]["lo"].get<double>() - std::acos(x)) < 1e-11);
  CHECK(ij["intervals"][0]["hi"] == std::numbers::pi);
  CHECK(ij["branch"] == "branch0");
  CHECK(ij["model"]["parameters"]["K"] == 0.5);

  // thresholds: nothing changes with g > 0 along w (the interval only moves).
  const auto th = run_lrchain({"regime", "thresholds", "--model", model, "--axis", "w", "--axis-range", "0.5", "2",
                               "--scan", "20"},
                              {}, env);
  INFO(th.err);
  REQUIRE(th.exit_code == 0);
  const auto tj = nlohmann::json::parse(th.out);
  CHECK(tj["scans"][0]["events"].empty());

  // An unbounded axis without a range, and a range outside the declared one: exit 2, nothing written.
  const auto unbounded = run_lrchain({"regime", "map", "--model", model, "--axis", "w", "--out", (dir / "m2").string()},
                                     {}, env);
  CHECK(unbounded.exit_code == 2);
  CHECK(unbounded.err.find("axis-range") != std::string::npos);
  const auto outside = run_lrchain(
      {"regime", "map", "--model", model, "--axis", "K", "--axis-range", "-1", "1", "--out", (dir / "m3").string()}, {},
      env);
  CHECK(outside.exit_code == 2);
  CHECK(!fs::exists(dir / "m2"));
  CHECK(!fs::exists(dir / "m3"));
  fs::remove_all(dir);
}

// A model file written outside models/ through `lrchain coeffs --model`: derived, compiled into the
// per-user cache under $XDG_CACHE_HOME/lrchain, loaded; a second call reuses the cached object.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>
#include <nlohmann/json.hpp>

#include "../support/run_lrchain.hpp"

namespace fs = std::filesystem;

TEST_CASE("a scratch model file is compiled once into the cache and evaluated by lrchain coeffs") {
  const fs::path dir = fs::temp_directory_path() / ("lrchain-user-model-test-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir / "cache");
  {
    // A Klein-Gordon chain with a quartic on-site force only: omega^2 = w^2 + 4 K sin^2(theta/2).
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
  const std::vector<std::string> args{"coeffs", "--model", (dir / "quartic_chain.toml").string(), "--set", "w=1.5",
                                      "--branch", "branch0", "--theta", "1.2", "--json"};
  const auto first = lrchain::test::run_lrchain(args, {}, env);
  INFO(first.err);
  REQUIRE(first.exit_code == 0);
  int cached = 0;
  for (const auto& e : fs::directory_iterator(dir / "cache" / "lrchain")) cached += e.path().extension() == ".so";
  CHECK(cached == 1);
  const auto second = lrchain::test::run_lrchain(args, {}, env);
  REQUIRE(second.exit_code == 0);
  // The same numbers from the cached object (provenance differs only in its date).
  const auto j = nlohmann::json::parse(first.out);
  auto without_provenance = [](nlohmann::json x) {
    x.erase("provenance");
    return x;
  };
  CHECK(without_provenance(nlohmann::json::parse(second.out)) == without_provenance(j));
  CHECK(j.contains("provenance"));
  const double expected = std::sqrt(1.5 * 1.5 + 4 * 0.2 * std::pow(std::sin(0.6), 2));  // textbook dispersion
  CHECK(std::abs(j["omega"].get<double>() - expected) < 1e-14 * expected);
  CHECK(j["model"]["name"] == "quartic_chain");
  CHECK(j["lambda"].is_null());  // on-site: no mean flow
  // With only a cubic on-site force, g u^3 with u ~ eps (A E + c.c.) puts 3 g |A|^2 A on E^1 and no
  // second harmonic is driven, so h = 3 g gamma / 2 with gamma = 1/omega at every theta (at theta = 0
  // this is Landau & Lifshitz Sec. 28's shift 3 g X^2/(8 w) = (h/4) X^2, docs/models.md).
  CHECK(std::abs(j["h"].get<double>() - 1.5 * (1.0 / 3.0) / expected) < 1e-12 * j["h"].get<double>());
  fs::remove_all(dir);
}

TEST_CASE("a bad user model file exits 2 with one line naming the file and line") {
  const fs::path dir = fs::temp_directory_path() / ("lrchain-user-model-bad-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  {
    std::ofstream f(dir / "bad.toml");
    f << "name = \"bad\"\n[parameters]\nK = { default = 1 }\n[[field]]\nname = \"u\"\nforce = \"K*(u[n+4] - u[n])\"\n";
  }
  const auto r = lrchain::test::run_lrchain({"coeffs", "--model", (dir / "bad.toml").string(), "--branch", "acoustic",
                                             "--theta", "1"},
                                            {}, {"XDG_CACHE_HOME=" + (dir / "cache").string()});
  CHECK(r.exit_code == 2);
  CHECK(r.err.find("bad.toml:6") != std::string::npos);
  CHECK(r.err.find("shift beyond") != std::string::npos);
  CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
  CHECK(!fs::exists(dir / "cache"));  // nothing written
  fs::remove_all(dir);
}

TEST_CASE("without the C++ compiler a user model is evaluated through GiNaC with one warning line") {
  const fs::path dir = fs::temp_directory_path() / ("lrchain-user-model-no-compiler-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir / "cache");
  {
    std::ofstream f(dir / "cubic_chain.toml");
    f << "name = \"cubic_chain\"\n[parameters]\nK = { default = \"1/5\", range = \"(0, inf)\" }\n"
         "a = { default = \"1/4\" }\n[[field]]\nname = \"u\"\nforce = \"K*(u[n+1] - 2*u[n] + u[n-1]) - u[n] - a*u[n]^2\"\n";
  }
  const std::vector<std::string> args{"coeffs", "--model", (dir / "cubic_chain.toml").string(), "--branch", "branch0",
                                      "--theta", "2.1", "--json"};
  const std::string cache = "XDG_CACHE_HOME=" + (dir / "cache").string();
  const auto compiled = lrchain::test::run_lrchain(args, {}, {cache});
  // The real detection path: the compiler named by LRCHAIN_MODEL_CXX does not exist.
  const auto fallback =
      lrchain::test::run_lrchain(args, {}, {cache, "LRCHAIN_MODEL_CXX=/nonexistent/lrchain-no-such-c++"});
  INFO(fallback.err);
  REQUIRE(compiled.exit_code == 0);
  REQUIRE(fallback.exit_code == 0);
  CHECK(compiled.err.empty());
  CHECK(std::count(fallback.err.begin(), fallback.err.end(), '\n') == 1);
  CHECK(fallback.err.find("warning") != std::string::npos);
  CHECK(fallback.err.find("/nonexistent/lrchain-no-such-c++") != std::string::npos);
  CHECK(fallback.err.find("apt install g++") != std::string::npos);
  const auto x = nlohmann::json::parse(compiled.out), y = nlohmann::json::parse(fallback.out);
  for (const char* key : {"omega", "group_velocity", "curvature", "gamma", "h", "h_tilde", "nonresonance1"}) {
    INFO(key);
    const double u = x[key].get<double>(), v = y[key].get<double>();
    CHECK(std::abs(u - v) <= 1e-12 * std::abs(u));
  }
  CHECK(y["regime"] == x["regime"]);
  fs::remove_all(dir);
}

// `lrchain dark ... --model` with one-sided contacts: the resonant chain's model file at branch points
// whose orbits open contacts every period (site-centred; rho = 1/3 at omega_b = 2.42, K_x = 0.473 >
// delta0, the amplitude of dark_breather_test.cpp; rho = 1 at 2.207, K_x = 0.662) gives the specialised
// strain-lattice breather (shooting.hpp, contact changes located there too) with the same contact
// changes; a smooth model (klein_gordon) reports no contacts; `dark evolve --model` writes the paper
// chain's evolution files and figures; `dark continue --model` counts contact changes per point; a
// user's copy of the model file (lattice code compiled at run time) exports the same contacts.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>
#include <string>
#include <unistd.h>
#include <vector>

#include <nlohmann/json.hpp>

#include "../support/renamed_model.hpp"
#include "../support/run_lrchain.hpp"
#include "lrchain/ansatz/dark_breather.hpp"
#include "lrchain/sim/dark/contact_integrator.hpp"
#include "lrchain/sim/dark/measures.hpp"
#include "lrchain/sim/dark/shooting.hpp"

namespace fs = std::filesystem;
using lrchain::test::run_lrchain;

namespace {

const fs::path source_dir = LRCHAIN_SOURCE_DIR;

fs::path scratch(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("lrchain-" + name + "-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  return dir;
}

// Rows of a CSV file with a header row, as numbers.
std::vector<std::vector<double>> read_csv(const fs::path& file) {
  std::ifstream in(file);
  std::string line;
  std::getline(in, line);
  std::vector<std::vector<double>> rows;
  while (std::getline(in, line)) {
    std::vector<double> row;
    std::stringstream ss(line);
    std::string cell;
    while (std::getline(ss, cell, ',')) row.push_back(std::stod(cell));
    rows.push_back(row);
  }
  return rows;
}

// A site-centred breather of the resonant chain at rho (model file: --set rho=rho_text) and omega_b on
// 41 sites, through `dark solve --model` and through the strain-lattice solver: their contact changes
// per period, E_b(T_b), K_x and profile.
void check_against_strain_lattice(const std::string& rho_text, double rho, const std::string& omega_text) {
  using namespace lrchain;
  using namespace lrchain::sim::dark;
  const double omega_b = std::stod(omega_text);
  const int N = 41;
  const fs::path out = scratch("dark-model-contact");
  const auto r = run_lrchain({"dark", "solve", "--model", "models/resonant_chain.toml", "--set", "rho=" + rho_text,
                              "--branch", "optical", "--omega-b", omega_text, "--center", "site", "--sites", "41",
                              "--quiet", "--figure-format", "png", "--out", out.string()},
                             source_dir);
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  const auto j = nlohmann::json::parse(r.out);
  REQUIRE(j["newton_converged"] == true);
  CHECK(j["contact_changes_located"] == true);
  REQUIRE(j["one_sided_contacts"].size() == 1);  // one Hertz bond law: F(u[n+1] - u[n]) = F(r[n+1]) up to a shift
  const long changes = j["contact_changes_per_period"].get<long>();
  CHECK(changes > 0);
  CHECK(changes % 2 == 0);  // every contact opened in a period closes again

  // The specialised solver (Params path) at the same point.
  Params p;  // alpha 3/2, delta0 4/9, kappa 1: the model file's defaults
  p.rho = rho;
  const DarkShooting sh(p, N, DarkCenter::site, ShootingMode::reversible);
  const auto res = newton_solve(
      sh, sh.unknowns_from_z(dark_seed(make_dark_breather_ansatz(p, Branch::optical, omega_b), DarkCenter::site, N)),
      omega_b, {});
  REQUIRE(res.converged);
  const Eigen::VectorXd xy = sh.z_from_unknowns(res.q);
  const DarkMeasures m = measure_dark_breather(p, xy, omega_b);
  REQUIRE(m.max_strain > p.delta0);  // the paper chain's orbit loses contact every period
  // Its contact changes over one period, located by the strain lattice's own integrator.
  const StrainLatticeOrbit orbit(p, N);
  ContactIntegrator integrator(orbit);
  std::vector<double> state(orbit.orbit_size(), 0.0);
  std::copy(xy.data(), xy.data() + xy.size(), state.begin());
  integrator.integrate(state, 0.0, 2 * std::numbers::pi / omega_b);
  const long paper_changes = integrator.stats().contact_changes;

  // profile.csv: n, r_0, r_seed, r_T, w1_0, w1_seed, w1_T; (r, w) -> (x, y): x_n = r_n,
  // y_n = r_n + w_n - w_{n-1} (periodic).
  const auto rows = read_csv(out / "profile.csv");
  REQUIRE(rows.size() == std::size_t(N));
  double profile = 0;
  for (int n = 0; n < N; ++n) {
    const double x = rows[std::size_t(n)][1], y = x + rows[std::size_t(n)][4] - rows[std::size_t((n + N - 1) % N)][4];
    profile = std::max({profile, std::abs(x - xy(n)), std::abs(y - xy(N + n))});
  }
  const double E_b = j["measures"]["E_b"].get<double>(), K_x = j["measures"]["K_x"].get<double>();
  std::printf("dark resonant_chain model vs Params at rho %s, omega_b %s, site-centred (contacts open): %ld vs %ld "
              "contact changes per period, E_b %.3e vs %.3e, K_x %.15f vs %.15f, max profile difference %.3e\n",
              rho_text.c_str(), omega_text.c_str(), changes, paper_changes, E_b, m.E_b, K_x, m.K_x, profile);
  CHECK(changes == paper_changes);  // the same bonds open and close
  // Both exact to the 1e-10 (dark_breather_test.cpp: the Params path reaches it at 2.42).
  CHECK(E_b <= 1e-10);
  CHECK(m.E_b <= 1e-10);
  // Same breather (measured: 5.9e-11 and 9.5e-11 in the profile, 6e-12 and 9e-11 in K_x). Bond-centred
  // seeds are worse conditioned on the model path, which imposes no reflection symmetry: at rho = 1/3,
  // 2.425 the two bond solutions differ by 2.4e-4 in the profile with both E_b ~ 2e-12, at 2.435, with
  // no contact change, by 7.7e-4 (the weakly pinned dip position, docs/dark-models.md).
  CHECK(profile < 1e-9);
  CHECK(std::abs(K_x - m.K_x) < 1e-9);
  fs::remove_all(out);
}

}  // namespace

TEST_CASE("dark --model: the resonant chain's model file opens contacts and gives the strain-lattice breather" *
          doctest::test_suite("fast")) {
  check_against_strain_lattice("1/3", 1.0 / 3.0, "2.42");  // K_x = 0.473 > delta0 (dark_breather_test.cpp)
  check_against_strain_lattice("1", 1.0, "2.207");         // K_x = 0.662: the rho = 1 site branch (Fig. 25)
}

TEST_CASE("dark --model: a smooth model (klein_gordon) has no one-sided contacts" * doctest::test_suite("fast")) {
  const auto r = run_lrchain({"dark", "solve", "--model", "models/klein_gordon.toml", "--set", "b=-1/2", "--omega-b",
                              "1.17", "--sites", "31", "--quiet", "--json"},
                             source_dir);
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  const auto j = nlohmann::json::parse(r.out);
  CHECK(j["one_sided_contacts"].empty());
  CHECK(j["contact_changes_located"] == false);
  CHECK(j["contact_changes_per_period"].is_null());
  CHECK(j["measures"]["E_b"].get<double>() < 1e-10);
  // Continuation: every point says null (no contact located), never a count.
  const auto c = run_lrchain({"dark", "continue", "--model", "models/klein_gordon.toml", "--set", "b=-1/2", "--omega-b",
                              "1.17", "--sites", "15", "--points", "2", "--ds", "0.02", "--quiet", "--json"},
                             source_dir);
  INFO(c.err);
  REQUIRE(c.exit_code == 0);
  const auto branch = nlohmann::json::parse(c.out);
  REQUIRE(branch["branch_points"].size() == 2);
  for (const auto& point : branch["branch_points"]) CHECK(point["contact_changes_per_period"].is_null());
  CHECK(branch["contact_changes_per_period"].is_null());
}

TEST_CASE("dark continue --model: every branch point reports its own contact changes" * doctest::test_suite("fast")) {
  // The resonant chain's site-centred breather at omega_b = 2.42 (contacts open every period) on 15
  // sites: the first point is the solved breather, so its count is `dark solve`'s; each point's
  // count is located on that point's own orbit (even: every contact opened in a period closes).
  const std::vector<std::string> common{"--model", "models/resonant_chain.toml", "--branch", "optical", "--center",
                                        "site", "--omega-b", "2.42", "--sites", "15", "--quiet", "--json"};
  std::vector<std::string> solve{"dark", "solve"}, branch{"dark", "continue", "--points", "3", "--ds", "0.5"};
  solve.insert(solve.end(), common.begin(), common.end());
  branch.insert(branch.end(), common.begin(), common.end());
  const auto s = run_lrchain(solve, source_dir);
  const auto b = run_lrchain(branch, source_dir);
  INFO(s.err << b.err);
  REQUIRE(s.exit_code == 0);
  REQUIRE(b.exit_code == 0);
  const auto solved = nlohmann::json::parse(s.out), j = nlohmann::json::parse(b.out);
  REQUIRE(j["branch_points"].size() == 3);
  CHECK(j["branch_points"][0]["contact_changes_per_period"] == solved["contact_changes_per_period"]);
  CHECK(j["contact_changes_per_period"] == solved["contact_changes_per_period"]);
  double previous = 1e300;
  for (const auto& point : j["branch_points"]) {
    const long changes = point["contact_changes_per_period"].get<long>();
    CHECK(changes > 0);
    CHECK(changes % 2 == 0);
    CHECK(point["omega_b"].get<double>() < previous);  // into the gap, away from the edge
    previous = point["omega_b"].get<double>();
  }
}

TEST_CASE("dark evolve --model: the paper chain's evolution files and figures" * doctest::test_suite("fast")) {
  const fs::path out = scratch("dark-model-evolve");
  const auto r = run_lrchain({"dark", "evolve", "--model", "models/klein_gordon.toml", "--set", "b=-1/2", "--omega-b",
                              "1.17", "--sites", "31", "--t-end", "60", "--quiet", "--figure-format", "png", "--out",
                              out.string()},
                             source_dir);
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  for (const char* name : {"u0_spacetime.bin", "evolution.csv", "snapshots.csv", "evolution.gp", "diagnostics.gp",
                           "summary.json"}) {
    INFO(name);
    REQUIRE(fs::exists(out / name));
    CHECK(fs::file_size(out / name) > 0);
  }
  std::ifstream gp(out / "evolution.gp");
  const std::string script((std::istreambuf_iterator<char>(gp)), std::istreambuf_iterator<char>());
  CHECK(script.find("set xlabel 'site n'") != std::string::npos);
  CHECK(script.find("set ylabel 't (dimensionless)'") != std::string::npos);
  CHECK(script.find("set cblabel 'u0[n]'") != std::string::npos);
  fs::remove_all(out);
}

TEST_CASE("dark solve --model: a user's copy of the resonant chain (lattice code compiled at run time) locates the same contacts" *
          doctest::test_suite("fast")) {
  // A renamed copy of models/resonant_chain.toml outside models/: its lattice code, with the contact
  // table, is generated and compiled into a fresh cache. Same equations, so the same bond and the same
  // contact changes as the shipped model on 15 sites (18 per period, measured); E_b to the 1e-10.
  const fs::path dir = scratch("dark-user-contacts");
  fs::create_directories(dir);
  const auto [ja, jb] = lrchain::test::dark_solve_shipped_and_renamed(
      source_dir, "resonant_chain", "my_resonant_chain", dir,
      {"--branch", "optical", "--center", "site", "--omega-b", "2.42", "--sites", "15", "--quiet", "--json"});
  CHECK(jb["model"]["name"] == "my_resonant_chain");
  CHECK(jb["one_sided_contacts"] == ja["one_sided_contacts"]);
  CHECK(jb["one_sided_contacts"] == nlohmann::json::array({"F(u[n+1] - u[n])"}));
  CHECK(jb["contact_changes_per_period"].get<long>() > 0);
  CHECK(jb["contact_changes_per_period"] == ja["contact_changes_per_period"]);
  CHECK(jb["measures"]["E_b"].get<double>() < 1e-10);
  CHECK(jb["measures"]["K_x"].get<double>() == doctest::Approx(ja["measures"]["K_x"].get<double>()).epsilon(1e-9));
  fs::remove_all(dir);
}

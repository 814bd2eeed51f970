// Model files (models/*.toml, docs/models.md) through the engine: every shipped model derives and
// passes its checks (its derivation time is printed; speed targets live in benchmarks); results the engine did not come from (Landau & Lifshitz's anharmonic
// oscillator, the textbook diatomic chain); one bad file per error kind; `lrchain derive` exit codes.
#include <doctest/doctest.h>

#include <nlohmann/json.hpp>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <tuple>

#include "lrchain/derivation/model_derivation.hpp"
#include "lrchain/errors.hpp"
#include "lrchain/process.hpp"

using namespace lrchain::derivation;
namespace fs = std::filesystem;

namespace {

fs::path model_path(const std::string& name) { return fs::path(LRCHAIN_SOURCE_DIR) / "models" / (name + ".toml"); }

std::unique_ptr<ModelDerivation> derive_shipped(const std::string& name, const Symbols& s,
                                                const std::vector<std::pair<std::string, std::string>>& set = {}) {
  ModelFile f = load_model_file(model_path(name));
  const GiNaC::exmap values = parameter_values(f, set);
  return derive_model(std::move(f), values, s);
}

// The InputError message for a model text, "" when it loads (and derives) without one.
std::string error_of(const std::string& text) {
  try {
    const Symbols s;
    ModelFile f = parse_model_text(text, "bad.toml");
    const GiNaC::exmap values = parameter_values(f, {});
    derive_model(std::move(f), values, s);
  } catch (const lrchain::InputError& e) {
    return e.what();
  }
  return "";
}

const char* kGoodKleinGordon = R"toml(name = "kg"
[parameters]
C = { default = "1/10", range = "[0, inf)" }
w0 = { default = 1, range = "(0, inf)" }
[[field]]
name = "u"
mass = "1"
force = "C*(u[n+1] - 2*u[n] + u[n-1]) - w0^2*u[n] - u[n]^3"
)toml";

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  REQUIRE(at != std::string::npos);
  return text.replace(at, from.size(), to);
}

}  // namespace

TEST_CASE("every shipped model derives and passes all its checks (times printed, not asserted)") {
  const Symbols s;
  for (const std::string name : {"resonant_chain", "homogeneous_chain", "fput", "klein_gordon", "newtons_cradle",
                                 "diatomic_chain", "resonant_chain_polynomial"}) {
    const auto t0 = std::chrono::steady_clock::now();
    const auto m = derive_shipped(name, s);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    std::printf("%-26s %s, %zu branch(es), %zu checks, derivation %.3f s, checks %.3f s, total %.3f s\n", name.c_str(),
                m->coefficients.mean_flow ? "mean flow" : "on-site", m->branches.size(), m->checks.size(),
                m->derive_seconds, m->check_seconds, seconds);
    for (const auto& c : m->checks) {
      INFO(name << ": " << c.name << " (" << c.method << ": " << c.detail << ")");
      CHECK(c.passed);
    }
    CHECK(m->checks.size() >= 5);
    // The case follows from the model: on-site forces (w0^2 u) make L_0 regular.
    const bool on_site = name == "klein_gordon" || name == "newtons_cradle";
    CHECK(m->coefficients.mean_flow == !on_site);
  }
}

TEST_CASE("resonant_chain.toml runs the reference and all paper checks — branches acoustic/optical") {
  const Symbols s;
  const auto m = derive_shipped("resonant_chain", s);
  int paper = 0;
  for (const auto& c : m->checks) paper += c.name.rfind("paper: ", 0) == 0;
  CHECK(paper >= 27);  // every check of run_paper_checks, on the file's coefficients
  REQUIRE(m->branches.size() == 2);
  CHECK(m->branches[0].name == "acoustic");
  CHECK(m->branches[1].name == "optical");
  // (eq:disp1d) at theta = 0, default parameters (kappa = 1, rho = 1/3): omega^2 = kappa (1 + rho)/rho = 4.
  CHECK(m->branches[1].omega_at_zero == doctest::Approx(2.0).epsilon(1e-12));
}

TEST_CASE("klein_gordon, C -> 0: h equals 4x the anharmonic oscillator's shift (Landau & Lifshitz, Mechanics, sec. 28)") {
  // L&L: x'' + w0^2 x + a x^2 + b x^3 = 0 has omega = w0 + (3b/(8 w0) - 5a^2/(12 w0^3)) A^2 for x ~ A cos(omega t).
  // Our ansatz: u = eps (A_{1,1} E + c.c.) + ..., so x's amplitude is 2 eps |A_{1,1}|; the NLS
  // i A_tau - h |A|^2 A = 0 gives the frequency omega + eps^2 h |A_{1,1}|^2 = omega + (h/4) x_amplitude^2.
  const Symbols s;
  const auto m = derive_shipped("klein_gordon", s);
  const ModelFile& f = m->file;
  GiNaC::ex C, w0, a, b;
  for (const auto& p : f.parameters) {
    if (p.name == "C") C = p.symbol;
    if (p.name == "w0") w0 = p.symbol;
    if (p.name == "a") a = p.symbol;
    if (p.name == "b") b = p.symbol;
  }
  const GiNaC::ex landau_lifshitz = 3 * b / (8 * w0) - 5 * pow(a, 2) / (12 * pow(w0, 3));
  // Symbolically: C = 0 puts omega = w0 on the dispersion relation, for every theta.
  const GiNaC::ex h0 = m->coefficients.h.subs(C == 0).subs(s.omega == w0);
  CHECK(GiNaC::normal(h0 / 4 - landau_lifshitz).is_zero());
  // Numerically at C = 1e-9 (not 0), w0 = 1.3, a = 0.7, b = 0.4, theta = 1: L&L gives 0.0224549...
  const auto small = derive_shipped("klein_gordon", s, {{"C", "1e-9"}, {"w0", "1.3"}, {"a", "0.7"}, {"b", "0.4"}});
  const BranchPoint p(small->coefficients, s, small->values, 1.0, 0);
  const double shift = p.value(small->coefficients.h).to_double() / 4;
  const double expected = 3 * 0.4 / (8 * 1.3) - 5 * 0.49 / (12 * 1.3 * 1.3 * 1.3);
  std::printf("klein_gordon C = 1e-9: h/4 = %.12f, Landau-Lifshitz 3b/(8w0) - 5a^2/(12w0^3) = %.12f\n", shift, expected);
  CHECK(shift == doctest::Approx(expected).epsilon(1e-7));
  CHECK(small->coefficients.mean_flow == false);
  CHECK(small->branches.at(0).name == "branch0");
}

TEST_CASE("diatomic_chain: linear dispersion = textbook acoustic/optical branches with spring K2 (theta per cell)") {
  // Masses 1 and m, spring K2, theta = wavenumber x cell length:
  // omega^2 = K2 (1 + 1/m) -+ K2 sqrt((1 + 1/m)^2 - 4 sin^2(theta/2)/m)  (e.g. Kittel, ch. 4; Ashcroft-Mermin, ch. 22).
  const Symbols s;
  for (const auto& [delta0, mass] : {std::pair{"4/9", "2"}, std::pair{"0.1", "3"}, std::pair{"1", "0.25"}}) {
    const auto m = derive_shipped("diatomic_chain", s, {{"delta0", delta0}, {"m", mass}});
    REQUIRE(m->branches.size() == 2);
    CHECK(m->branches[0].name == "acoustic");
    CHECK(m->branches[1].name == "optical");
    const double d0 = GiNaC::ex_to<GiNaC::numeric>(m->values.at(m->file.parameters[1].symbol)).to_double();
    const double mm = GiNaC::ex_to<GiNaC::numeric>(m->values.at(m->file.parameters[2].symbol)).to_double();
    const double K2 = 1.5 * std::sqrt(d0);  // alpha delta0^(alpha - 1), alpha = 3/2
    double worst = 0;
    for (double theta : {0.1, 0.5, 1.0, 2.0, 3.0, M_PI}) {
      bool complex_roots = true;
      const auto w2 = omega_squared_roots(m->coefficients, s, m->values, theta, complex_roots);
      CHECK_FALSE(complex_roots);
      const double root = std::sqrt(std::pow(1 + 1 / mm, 2) - 4 * std::pow(std::sin(theta / 2), 2) / mm);
      const double acoustic = K2 * (1 + 1 / mm - root), optical = K2 * (1 + 1 / mm + root);
      worst = std::max({worst, std::abs(w2.at(0) - acoustic) / optical, std::abs(w2.at(1) - optical) / optical});
    }
    std::printf("diatomic delta0 = %s, m = %s (K2 = %.6f): max relative difference of omega^2 from the textbook %.2e\n",
                delta0, mass, K2, worst);
    CHECK(worst < 1e-12);
  }
}

TEST_CASE("shifts up to +-3 and three fields: long-range chain dispersion, two resonators per bead") {
  // u'' = F(u[n+1]-u[n]) - F(u[n]-u[n-1]) + sum_{m=2,3} k_m (u[n+m] - 2u[n] + u[n-m]), F(r) = r + b r^3:
  // omega^2 = sum_{m=1..3} k_m 4 sin^2(m theta/2) with k1 = 1 (direct computation of the linear modes).
  const Symbols s;
  ModelFile f = parse_model_text(R"toml(name = "long_range"
[parameters]
k2 = { default = "1/4" }
k3 = { default = "1/9" }
b = { default = "1/2" }
[functions.F]
argument = "r"
expression = "r + b*r^3"
[[field]]
name = "u"
force = "F(u[n+1]-u[n]) - F(u[n]-u[n-1]) + k2*(u[n+2] - 2*u[n] + u[n-2]) + k3*(u[n+3] - 2*u[n] + u[n-3])"
)toml", "long_range.toml");
  const GiNaC::exmap values = parameter_values(f, {});
  const auto m = derive_model(std::move(f), values, s);
  CHECK(m->passed());
  double worst = 0;
  for (double theta : {0.2, 0.9, 1.7, 2.5, M_PI}) {
    bool complex_roots = true;
    const auto w2 = omega_squared_roots(m->coefficients, s, m->values, theta, complex_roots);
    double expected = 0;
    for (int k = 1; k <= 3; ++k) expected += 4 * std::pow(std::sin(k * theta / 2), 2) / (k * k);  // k_m = 1/m^2
    worst = std::max(worst, std::abs(w2.at(0) - expected) / expected);
  }
  CHECK(worst < 1e-13);

  // Three fields: a bead u with two resonators v (mass rho, spring kappa) and w (mass s2, spring mu).
  ModelFile three = parse_model_text(R"toml(name = "two_resonators"
[parameters]
kappa = { default = 1 }
mu = { default = 2 }
rho = { default = "1/3" }
s2 = { default = "1/5" }
[functions.F]
argument = "r"
expression = "r - r^2/4 + r^3/2"
[[field]]
name = "u"
force = "F(u[n+1] - u[n]) - F(u[n] - u[n-1]) - kappa*(u - v) - mu*(u - w)"
[[field]]
name = "v"
mass = "rho"
force = "kappa*(u - v)"
[[field]]
name = "w"
mass = "s2"
force = "mu*(u - w)"
)toml", "three.toml");
  const GiNaC::exmap three_values = parameter_values(three, {});
  const auto t = derive_model(std::move(three), three_values, s);
  for (const auto& c : t->checks) {
    INFO(c.name << " (" << c.detail << ")");
    CHECK(c.passed);
  }
  REQUIRE(t->branches.size() == 3);
  CHECK(t->branches[0].name == "acoustic");
  CHECK(t->branches[1].name == "optical1");
  CHECK(t->branches[2].name == "optical2");
  // theta = 0, optical branches: the uniform-motion frequencies (hand-derived equation below).
  for (std::size_t i = 1; i < 3; ++i) {
    const double w2 = t->branches[i].omega_at_zero * t->branches[i].omega_at_zero;
    // Uniform motion: -w^2 u = -kappa(u - v) - mu(u - w), v = kappa u/(kappa - rho w^2), w = mu u/(mu - s2 w^2).
    const double residual = -w2 + 1.0 * (1 - 1.0 / (1 - w2 / 3.0)) + 2.0 * (1 - 1.0 / (1 - w2 / 10.0));
    CHECK(std::abs(residual) < 1e-9);
  }
}

// A law whose Taylor coefficients are sums of parameters, (1 + a1 + b1)(r + a1 r^2 + b1 r^3), gets
// automatic names F_d1, F_d2, F_d3 (docs/models.md): the three-field derivation took 105-190 s
// before, about 1 s now. Expected values: the same chain with the factor as a parameter s set to
// 1 + a1 + b1 = 7/4, a law whose coefficients s, s a1, s b1 are not sums (derived without names).
TEST_CASE("a law with sums of parameters as coefficients: named automatically, same coefficients") {
  const std::string chain = R"toml(name = "mass_in_mass3"
[parameters]
a1 = { default = "1/4", range = "(-inf, inf)" }
b1 = { default = "1/2", range = "(-inf, inf)" }
s = { default = "7/4", range = "(0, inf)" }
k2 = { default = 1, range = "(0, inf)" }
m2 = { default = "1/2", range = "(0, inf)" }
k3 = { default = "1/2", range = "(0, inf)" }
g3 = { default = 1, range = "(-inf, inf)" }
m3 = { default = "1/4", range = "(0, inf)" }
[functions.F]
argument = "r"
expression = "LAW"
[functions.G]
argument = "x"
expression = "k3*x + g3*x^3"
[[field]]
name = "u"
force = "F(u[n+1] - u[n]) - F(u[n] - u[n-1]) - k2*(u[n] - v[n])"
[[field]]
name = "v"
mass = "m2"
force = "k2*(u[n] - v[n]) - G(v[n] - w[n])"
[[field]]
name = "w"
mass = "m3"
force = "G(v[n] - w[n])"
)toml";
  const Symbols s;
  ModelFile summed = parse_model_text(replaced(chain, "LAW", "(1 + a1 + b1)*(r + a1*r^2 + b1*r^3)"), "summed.toml");
  ModelFile scaled = parse_model_text(replaced(chain, "LAW", "s*r + s*a1*r^2 + s*b1*r^3"), "scaled.toml");
  std::vector<std::string> names;
  for (const auto& i : summed.intermediates) names.push_back(i.name);
  CHECK(names == std::vector<std::string>{"F_d1", "F_d2", "F_d3"});
  CHECK(scaled.intermediates.empty());
  const GiNaC::exmap summed_values = parameter_values(summed, {}), scaled_values = parameter_values(scaled, {});
  const auto a = derive_model(std::move(summed), summed_values, s);
  const auto b = derive_model(std::move(scaled), scaled_values, s);
  for (const auto& c : a->checks) {
    INFO(c.name << " (" << c.detail << ")");
    CHECK(c.passed);
  }
  REQUIRE(a->branches.size() == 3);
  for (std::size_t branch = 0; branch < 3; ++branch)
    for (const double theta : {0.4, 1.3, 2.9}) {
      const BranchPoint pa(a->coefficients, s, a->values, theta, branch), pb(b->coefficients, s, b->values, theta, branch);
      for (const auto& [name, ea, eb] : {std::tuple{"omega''", a->coefficients.curvature, b->coefficients.curvature},
                                         std::tuple{"h", a->coefficients.h, b->coefficients.h},
                                         std::tuple{"h_tilde", a->coefficients.h_tilde, b->coefficients.h_tilde}}) {
        INFO(a->branches[branch].name << " theta = " << theta << ": " << name);
        const double va = pa.value(ea).to_double(), vb = pb.value(eb).to_double();
        CHECK(va == doctest::Approx(vb).epsilon(1e-12));
      }
    }
}

TEST_CASE("the kernel rescaling check can fail: a wrong coefficient is caught") {
  // Perturbed copy of klein_gordon's h: the check against the rescaled derivation must report it.
  const Symbols s;
  auto m = derive_shipped("klein_gordon", s);
  m->coefficients.h = m->coefficients.h * (1 + s.D1 / 100);
  m->coefficients.h_tilde = m->coefficients.h;
  bool caught = false;
  for (const auto& c : run_model_checks(*m, s))
    if (c.name.find("left kernel is rescaled") != std::string::npos) caught = !c.passed;
  CHECK(caught);
}

TEST_CASE("bad model files: exit-2 errors name the file, the line and the problem") {
  CHECK(error_of(kGoodKleinGordon).empty());
  const std::string good = kGoodKleinGordon;
  // Unknown key, with its line and the closest valid key.
  CHECK(error_of(replaced(good, "mass = ", "mas = ")) == "bad.toml:7: unknown key 'mas' in [[field]] (allowed: name, mass, force; did you mean 'mass'?)");
  CHECK(error_of(replaced(good, "[parameters]", "[parameter]")).find("bad.toml:2: unknown key 'parameter'") == 0);
  // Undefined symbol, unknown field, shift beyond +-3.
  CHECK(error_of(replaced(good, "w0^2*u[n]", "w1^2*u[n]")) == "bad.toml:8: force of field u: undefined symbol 'w1' (did you mean 'w0'?)");
  CHECK(error_of(replaced(good, "u[n+1]", "v[n+1]")).find("bad.toml:8: force of field u: unknown field 'v[n+1]'") == 0);
  CHECK(error_of(replaced(good, "u[n+1]", "u[n+4]")).find("bad.toml:8: force of field u: shift beyond +-3 in 'u[n+4]'") == 0);
  CHECK(error_of(replaced(good, "u[n+1]", "u[k]")).find("index of 'u[k]' must be n, n+m or n-m") != std::string::npos);
  CHECK(error_of(replaced(good, "w0^2*u[n]", "G(u[n])")).find("undefined function 'G'") != std::string::npos);
  // A force that does not vanish at equilibrium.
  CHECK(error_of(replaced(good, "- u[n]^3", "- u[n]^3 + C")) == "bad.toml:8: force of field u: the force does not vanish at equilibrium (all fields zero): it is C");
  // A force law with a pole at its equilibrium (found by fuzzing: GiNaC's division by zero was exit 1).
  const std::string singular = replaced(replaced(good, "[[field]]", "[functions.F]\nargument = \"r\"\nexpression = \"1/r\"\n[[field]]"),
                                        "- u[n]^3", "- F(u[n])");
  CHECK(error_of(singular).find("bad.toml:11: force of field u: function F has no Taylor expansion about its equilibrium r = 0") == 0);
  // No real branch: u'' = C (...) + w0^2 u has omega^2 = C D1 - w0^2 < 0 for C = 1/10, w0 = 1.
  CHECK(error_of(replaced(good, "- w0^2*u[n]", "+ w0^2*u[n]")).find("bad.toml: model kg has no real branch") == 0);
  // A default outside its declared range; a --set value outside it.
  CHECK(error_of(replaced(good, "default = 1, range = \"(0, inf)\"", "default = -1, range = \"(0, inf)\"")) ==
        "bad.toml:4: parameter w0: default -1 is outside its range (0, inf)");
  const ModelFile f = parse_model_text(good, "bad.toml");
  CHECK_THROWS_WITH_AS(parameter_values(f, {{"C", "-0.5"}}), "invalid C: -1/2 is outside its range [0, inf)", lrchain::InvalidParameter);
  CHECK_THROWS_WITH_AS(parameter_values(f, {{"W0", "1"}}), "--set W0: model kg has no parameter 'W0' (did you mean 'w0'?)", lrchain::InputError);
  // Syntax errors are reported with the line.
  CHECK(error_of(replaced(good, "name = \"u\"", "name = \"u")).find("bad.toml:6:") == 0);
}

TEST_CASE("lrchain derive: exit 0 with the report, 2 for a bad file (one line on stderr)") {
  const fs::path cli = fs::path(LRCHAIN_DERIVE).parent_path().parent_path() / "cli" / "lrchain";
  REQUIRE(fs::exists(cli));
  lrchain::ProcessOptions o;
  o.capture_stdout = true;
  o.capture_stderr = true;
  const auto ok = lrchain::run_program({cli.string(), "derive", "--model", model_path("klein_gordon").string(), "--json"}, o);
  CHECK(ok.ok());
  CHECK(ok.output.find('\n') == ok.output.size() - 1);  // --json: one line
  const auto report = nlohmann::json::parse(ok.output);
  CHECK(report.at("case") == "on_site");
  CHECK(report.contains("file_hash"));
  const auto bad = lrchain::run_program({cli.string(), "derive", "--model", model_path("klein_gordon").string(), "--set", "w0=-1"}, o);
  CHECK(bad.exit_code == 2);
  CHECK(bad.error_output == "lrchain: invalid w0: -1 is outside its range (0, inf)\n");
  const auto missing = lrchain::run_program({cli.string(), "derive", "--model", "/nonexistent/model.toml"}, o);
  CHECK(missing.exit_code == 2);
}

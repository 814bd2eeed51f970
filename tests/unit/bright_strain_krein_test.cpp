// Krein signatures in strain form (sim/bright/krein_signature.hpp: strain_krein_signatures, the lift
// ring_displacements_of_strain) against an independent computation, the displacement-form monodromy
// of the same breather lifted to displacements, and at a Krein collision of an fput breather.
#include <doctest/doctest.h>

#include <cmath>
#include <complex>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Eigenvalues>

#include <nlohmann/json.hpp>

#include "lrchain/jobs/bright_breather_job.hpp"
#include "lrchain/model.hpp"
#include "lrchain/sim/bright/branch_bifurcations.hpp"
#include "lrchain/sim/bright/bright_floquet.hpp"
#include "lrchain/sim/bright/krein_signature.hpp"
#include "lrchain/sim/dark/shooting.hpp"
#include "lrchain/sim/model_lattice.hpp"
#include "lrchain/sim/model_lattice_bloch.hpp"

using namespace lrchain;
using namespace lrchain::sim::bright;
using namespace lrchain::jobs::bright_breather;

namespace {

// The bright job (step, 31 sites) on a shipped model with parameter values set, REQUIRing a breather;
// `adjust` sets the rest of the config.
BrightBreatherResult bright_run(const Model& model, const char* name, BrightStep step, double omega_b,
                                const char* center, const std::function<void(BrightBreatherConfig&)>& adjust = {}) {
  BrightBreatherConfig c;
  c.step = step;
  c.model = &model;
  c.kernels = sim::shipped_lattice_kernels(name);
  c.omega_b = omega_b;
  c.sites = 31;
  c.center = center;
  if (adjust) adjust(c);
  validate(c);
  BrightBreatherResult r = run(c);
  INFO(failure(r).value_or(""));
  REQUIRE(!failure(r));
  return r;
}

// The mass of every position, field-major (as the job's position_masses).
Eigen::VectorXd masses_of(const lrchain_lattice_kernels& kernels, const std::vector<double>& parameters, Index sites) {
  std::vector<double> field_mass(std::size_t(kernels.fields));
  kernels.masses(parameters.data(), field_mass.data());
  Eigen::VectorXd m(kernels.fields * sites);
  for (Index f = 0; f < kernels.fields; ++f) m.segment(f * sites, sites).setConstant(field_mass[std::size_t(f)]);
  return m;
}

// A breather of a model with odd forces solved in strain form, its Z(0) lifted to displacements
// (sum r = 0 by the half-period antisymmetry r(t + T_b/2) = -r(t) of odd forces, so the lift closes on
// the ring) and its monodromy computed again in displacement form on the same ring: the strain-form
// signatures must be those of the displacement form, and the lifted eigenvectors its eigenvectors.
void check_against_displacement_form(const char* name, const std::vector<std::pair<std::string, double>>& values,
                                     double omega_b, const char* center, std::size_t expected_on_circle) {
  const Model model = shipped_model(name, values);
  const BrightBreatherResult r = bright_run(model, name, BrightStep::floquet, omega_b, center);
  REQUIRE(r.edge.mean_flow);
  const lrchain_lattice_kernels& kernels = *sim::shipped_lattice_kernels(name);
  const std::vector<double> parameters = sim::lattice_parameters(model);
  const Index sites = 31;
  CHECK(std::abs(r.z0.head(sites).sum()) < 1e-9);  // the ring closes (measured 3e-14)
  const Eigen::VectorXd masses = masses_of(kernels, parameters, sites);
  const sim::dark::DarkShooting strain(kernels, parameters, sites, true, sim::dark::ShootingMode::reversible);
  const sim::dark::DarkShooting displacement(kernels, parameters, sites, false, sim::dark::ShootingMode::reversible);
  Eigen::VectorXd u0(r.z0.size());
  sim::CompiledLattice(kernels, parameters, sites, true, sim::LatticeForm::strain).displacements_of(r.z0.data(), u0.data());
  const Eigen::MatrixXd mr = strain.monodromy(r.z0, omega_b), mu = displacement.monodromy(u0, omega_b);
  // both forms have four trivial multipliers near +1 (phase and translation, or total strain)
  const BrightFloquet fr = bright_floquet(mr, true), fu = bright_floquet(mu, true);
  REQUIRE(fr.trivial_found);
  REQUIRE(fu.trivial_found);
  const std::vector<KreinMultiplier> ks = strain_krein_signatures(mr, masses, sites, 1e-6, fr.trivial_distance);
  const std::vector<KreinMultiplier> kd = krein_signatures(mu, masses, 1e-6, fu.trivial_distance);
  REQUIRE(ks.size() == kd.size());
  CHECK(ks.size() == expected_on_circle);
  int plus = 0;
  for (std::size_t i = 0; i < ks.size(); ++i) {
    INFO("multiplier ", i, " at angle ", std::arg(ks[i].lambda));
    CHECK(std::abs(ks[i].lambda - kd[i].lambda) < 1e-9);  // measured 1e-15
    CHECK(ks[i].signature != 0);
    CHECK(ks[i].signature == kd[i].signature);
    plus += ks[i].signature > 0;
  }
  CHECK(plus > 0);  // both signatures occur, so a sign convention flipped in one form would show
  CHECK(plus < int(ks.size()));
  // The floquet step reports the same signatures (BrightBreatherResult::krein, the JSON's floquet.krein).
  REQUIRE(r.krein.size() == kd.size());
  for (std::size_t i = 0; i < kd.size(); ++i) {
    CHECK(std::abs(r.krein[i].lambda - kd[i].lambda) < 1e-9);
    CHECK(r.krein[i].signature == kd[i].signature);
  }
  // The lift of each strain-form eigenvector is an eigenvector of the displacement-form monodromy.
  Eigen::EigenSolver<Eigen::MatrixXd> solver(mr, true);
  for (Eigen::Index k = 0; k < solver.eigenvalues().size(); ++k) {
    const std::complex<double> l = solver.eigenvalues()[k];
    if (std::abs(l - 1.0) <= fr.trivial_distance * (1 + 1e-6)) continue;
    const Eigen::VectorXcd u = ring_displacements_of_strain(solver.eigenvectors().col(k), masses, sites);
    INFO("multiplier ", l);
    CHECK((mu * u - l * u).norm() <= 1e-9 * u.norm());  // measured 1e-14
  }
}

}  // namespace

TEST_CASE("bright strain form: Krein signatures of the fput Page mode equal the displacement form's" * doctest::test_suite("fast")) {
  // fput with a = 0 (odd force r + r^3/2), the bond-centred (Page) mode at omega_b = 2.2 on 31 sites:
  // stable (Sandusky, Page & Schmidt 1992), so all 62 - 4 non-trivial multipliers lie on the circle,
  // 29 in the upper half; measured: 10 with signature +1, 19 with -1.
  check_against_displacement_form("fput", {{"a", 0.0}}, 2.2, "bond", 29);
}

TEST_CASE("bright strain form: Krein signatures of a two-field lattice equal the displacement form's" * doctest::test_suite("fast")) {
  // resonant_chain_polynomial with odd forces (b1 = b2 = 0): beads and resonators, w1 = v - u
  // reconstructed by the lift; the site-centred breather above the optical band at omega_b = 2.6, 31
  // sites, is stable (measured), so all 124 - 4 non-trivial multipliers lie on the circle, 60 in the
  // upper half.
  check_against_displacement_form("resonant_chain_polynomial", {{"b1", 0.0}, {"b2", 0.0}}, 2.6, "site", 60);
}

TEST_CASE("bright strain form: the fput Page mode's Krein collision joins multipliers of opposite signature" * doctest::test_suite("fast")) {
  // fput at its defaults (a = 1/4, b = 1/2: a mean flow, so strain form only), the bond-centred breather
  // on 31 sites continued from omega_b = 2.2: stable there, unstable at the next point 2.2574; the
  // oscillatory instability is located at omega* = 2.2010332 (measured; multiplier 0.82601 + 0.56380 i,
  // angle 0.59923, modulus 1.00008 just past it).
  const Model fput = shipped_model("fput");
  const BrightBreatherResult r = bright_run(fput, "fput", BrightStep::branch, 2.2, "bond", [](BrightBreatherConfig& c) {
    c.points = 2, c.ds = 0.2;
  });
  REQUIRE(r.edge.mean_flow);
  REQUIRE(r.branch_krein.size() == 2);
  // stable at 2.2: all 62 - 4 non-trivial multipliers on the circle, 29 in the upper half, in the JSON
  const nlohmann::json first = to_json(r)["branch"]["branch_points"][0]["krein"];
  REQUIRE(first.is_array());
  CHECK(first.size() == 29);
  for (const auto& m : first) CHECK(std::abs(m["signature"].get<int>()) == 1);
  const BranchBifurcation* k = nullptr;
  for (const BranchBifurcation& b : r.bifurcations)
    if (b.kind == "krein_collision") k = &b;
  REQUIRE(k);
  REQUIRE(k->located);
  REQUIRE(k->multiplier);
  CHECK(k->omega_b == doctest::Approx(2.2010332).epsilon(1e-6));
  CHECK(std::abs(*k->multiplier) > 1 + 1e-6);
  const double angle = std::arg(*k->multiplier);
  // The Krein signatures within 3e-3 rad of the collision's angle, 1e-4 before and after it, on the
  // branch's last point solved there: before, MacKay's criterion (krein_signature.hpp) requires the pair
  // about to collide to carry opposite signatures (measured: 0.59713 with -1, 0.60049 with +1; the next
  // multipliers lie at 0.5839 and 0.5789, outside the window); after, the pair has left the circle.
  auto near_collision = [&](double to, bool stable) {
    const BrightBreatherResult s = bright_run(fput, "fput", BrightStep::branch, 2.2, "bond", [&](BrightBreatherConfig& c) {
      c.points = 20, c.ds = 0.2, c.locate_tolerance = 0, c.to = to;
    });
    REQUIRE(s.branch.points.back().omega_b == doctest::Approx(to).epsilon(1e-14));
    CHECK(s.branch_floquets.back().stable == stable);
    std::pair<int, int> signs{0, 0};  // +1, -1
    for (const KreinMultiplier& m : s.branch_krein.back())
      if (std::abs(std::arg(m.lambda) - angle) < 3e-3) (m.signature > 0 ? signs.first : signs.second)++;
    return signs;
  };
  CHECK(near_collision(k->omega_b - 1e-4, true) == std::pair<int, int>{1, 1});
  CHECK(near_collision(k->omega_b + 1e-4, false) == std::pair<int, int>{0, 0});
}

TEST_CASE("bright strain form: an eigenvector that does not close on the ring gets no signature" * doctest::test_suite("fast")) {
  // A ring of 2 sites, one field of mass 1, state (r0, r1, r0dot, r1dot), period 1. The difference mode
  // d = (r0 - r1)/sqrt(2) is an oscillator of frequency 0.7: multiplier exp(0.7 i), eigenvector r0 = -r1
  // = 1, r0dot = -r1dot = 0.7 i (sum r = 0: it closes), lifted to u = (1/2, -1/2), udot = 0.7 i u, so
  // Im(conj(u) udot) > 0: signature +1 (a positive-energy oscillator, as the displacement-form test in
  // bright_branch_bifurcations_test.cpp). The sum mode (r0 + r1)/sqrt(2), frequency 1.9, changes the
  // total strain (which a lattice conserves): it cannot be lifted, signature 0 (null in the JSON).
  const double w1 = 0.7, w2 = 1.9;
  auto oscillator = [](double w) {
    Eigen::Matrix2d m;
    m << std::cos(w), std::sin(w) / w, -w * std::sin(w), std::cos(w);
    return m;
  };
  Eigen::Matrix2d q;  // r = q (d, s), orthogonal
  q << 1, 1, -1, 1;
  q /= std::sqrt(2.0);
  Eigen::MatrixXd modes = Eigen::MatrixXd::Zero(4, 4);  // in (d, s, ddot, sdot)
  const Eigen::Matrix2d d = oscillator(w1), s = oscillator(w2);
  modes(0, 0) = d(0, 0), modes(0, 2) = d(0, 1), modes(2, 0) = d(1, 0), modes(2, 2) = d(1, 1);
  modes(1, 1) = s(0, 0), modes(1, 3) = s(0, 1), modes(3, 1) = s(1, 0), modes(3, 3) = s(1, 1);
  Eigen::MatrixXd change = Eigen::MatrixXd::Zero(4, 4);
  change.block(0, 0, 2, 2) = q, change.block(2, 2, 2, 2) = q;
  const Eigen::MatrixXd monodromy = change * modes * change.transpose();
  const std::vector<KreinMultiplier> k = strain_krein_signatures(monodromy, Eigen::Vector2d(1.0, 1.0), 2, 1e-9);
  REQUIRE(k.size() == 2);
  CHECK(std::arg(k[0].lambda) == doctest::Approx(w1).epsilon(1e-12));
  CHECK(k[0].signature == 1);
  CHECK(std::arg(k[1].lambda) == doctest::Approx(w2).epsilon(1e-12));
  CHECK(k[1].signature == 0);
  // the lift of the closing eigenvector: u = (1/2, -1/2) r0, udot = 0.7 i u
  Eigen::VectorXcd v(4);
  v << 1, -1, std::complex<double>(0, w1), std::complex<double>(0, -w1);
  const Eigen::VectorXcd u = ring_displacements_of_strain(v, Eigen::Vector2d(1.0, 1.0), 2);
  CHECK(std::abs(u[0] - 0.5) < 1e-15);
  CHECK(std::abs(u[1] + 0.5) < 1e-15);
  CHECK(std::abs(u[2] - std::complex<double>(0, 0.5 * w1)) < 1e-15);
  CHECK(std::abs(u[3] + std::complex<double>(0, 0.5 * w1)) < 1e-15);
}

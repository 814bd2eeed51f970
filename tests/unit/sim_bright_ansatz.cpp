// Unit tests of the bright-breather ansatz (eq:focus_app, eq:focus_ini; Sec. 4.1).
#include <doctest/doctest.h>

#include <cmath>
#include <numbers>

#include "lrchain/ansatz/bright_breather.hpp"
#include "lrchain/errors.hpp"

using namespace lrchain;

TEST_CASE("bright ansatz: paper numbers at theta = pi/2 and refusal outside the focusing regime" * doctest::test_suite("fast")) {
  const Params p;  // alpha 3/2, delta0 4/9, kappa 1, rho 1/3
  const BrightBreatherAnsatz a(p, Branch::optical, std::numbers::pi / 2);
  CHECK(a.omega_b() == doctest::Approx(2.1752).epsilon(5e-5));  // Sec. 4.2: omega_b = 2.1752
  CHECK(a.period() == doctest::Approx(2.8885).epsilon(2e-5));   // Sec. 4.2: T_b = 2.8885
  CHECK(a.omega_b() - a.omega() == doctest::Approx(-1e-4));     // s = sign(h_tilde) = -1
  // velocities are the time derivative of the displacements (eq:focus_ini vs eq:focus_app)
  const double h = 1e-5;
  for (double n : {-40.0, -3.0, 0.0, 7.0, 55.0}) {
    double u1, v1, u2, v2, du, dv;
    a.displacements(n, 0.3 - h, u1, v1);
    a.displacements(n, 0.3 + h, u2, v2);
    a.velocities(n, 0.3, du, dv);
    CHECK(du == doctest::Approx((u2 - u1) / (2 * h)).epsilon(1e-6));
    CHECK(dv == doctest::Approx((v2 - v1) / (2 * h)).epsilon(1e-6));
  }
  // theta = 2.5 > theta_c ~ 1.892 is defocusing on the optical branch (Sec. 4.2)
  CHECK_THROWS_AS(BrightBreatherAnsatz(p, Branch::optical, 2.5), InvalidParameter);
  // wrong detuning sign (omega_b above omega where h_tilde < 0)
  CHECK_THROWS_AS(BrightBreatherAnsatz(p, Branch::optical, std::numbers::pi / 2, 1e-4), InvalidParameter);
  // acoustic, theta = 1.87 (focusing interval (1.7841, 1.949)): omega_b = omega + 1e-4 = 1.2402
  const BrightBreatherAnsatz ac(p, Branch::acoustic, 1.87);
  CHECK(ac.omega_b() == doctest::Approx(1.2402).epsilon(1e-4));
}

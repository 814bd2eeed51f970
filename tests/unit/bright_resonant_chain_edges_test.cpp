// Why the paper's chain has no bright breather at a band edge, for any parameters: at theta = pi
// (sin theta = 0, c = omega' = 0) the paper's coefficients reduce to h = 24 K4 g, beta = -4 K3 g and
// lambda = -8 K3 / K2 (eq:h, eq:ppOmega, eq:lambda; g = (rho w^2 - kappa)^2 / (w (rho kappa^2 +
// (rho w^2 - kappa)^2)) > 0), so h_tilde = h - lambda beta = g (24 K4 - 32 K3^2 / K2). With the Hertz
// force's K2 = alpha d^(alpha-1), K3 = -alpha (alpha-1) d^(alpha-2)/2, K4 = alpha (alpha-1) (alpha-2)
// d^(alpha-3)/6 (d = delta0) this is h_tilde(pi) = -4 alpha^2 (alpha - 1) d^(alpha-3) g < 0 for every
// alpha > 1, on both branches. theta = pi is the top of each band (omega'' < 0), so omega'' h_tilde > 0:
// defocusing. The optical theta = 0 edge (the bottom of its band) has h_tilde = 0 (every term carries
// sin^2 or (1 - cos theta)^2): degenerate, no NLS seed. So `lrchain bright` refuses the chain at every
// parameter set (exit 2), and the NLS limit of an exact bright breather cannot be shown on it.
#include <cmath>
#include <numbers>
#include <string>
#include <doctest/doctest.h>

#include "lrchain/coefficients.hpp"
#include "lrchain/errors.hpp"
#include "lrchain/jobs/bright_breather_job.hpp"
#include "lrchain/model.hpp"
#include "lrchain/sim/model_lattice.hpp"

using namespace lrchain;

TEST_CASE("resonant chain: h_tilde at theta = pi is -4 alpha^2 (alpha - 1) delta0^(alpha-3) g, defocusing on both branches" * doctest::test_suite("fast")) {
  for (const double rho : {1.0 / 3, 3.0, 10.0})
    for (const double delta0 : {0.05, 4.0 / 9, 2.0})
      for (const double alpha : {1.2, 1.5, 2.5})
        for (const double kappa : {1.0, 5.0})
          for (const Branch branch : {Branch::optical, Branch::acoustic}) {
            const int branch_index = int(branch);
            CAPTURE(rho);
            CAPTURE(delta0);
            CAPTURE(alpha);
            CAPTURE(kappa);
            CAPTURE(branch_index);
            const NlsCoefficients n = coefficients(Params{alpha, delta0, kappa, rho}, branch, std::numbers::pi);
            const double w = n.omega, q = rho * w * w - kappa;
            const double g = q * q / (w * (rho * kappa * kappa + q * q));
            const double closed = -4 * alpha * alpha * (alpha - 1) * std::pow(delta0, alpha - 3) * g;
            CHECK(n.h_tilde == doctest::Approx(closed).epsilon(1e-9));
            CHECK(n.h_tilde < 0);
            CHECK(n.curvature < 0);  // the top of the band
          }
}

TEST_CASE("bright job: the paper's chain is refused at its defaults and at the paper's other parameters" * doctest::test_suite("fast")) {
  using namespace lrchain::jobs::bright_breather;
  // rho = 1/3 (Fig. 1), rho = 3 and 10 (Fig. 3), rho = 17.8 (Fig. 4), each with omega_b just above the
  // optical band's top: no focusing edge, named by the check, with omega'' h_tilde > 0 at theta = pi.
  for (const double rho : {1.0 / 3, 3.0, 10.0, 17.8}) {
    CAPTURE(rho);
    const Model chain = shipped_model("resonant_chain", {{"rho", rho}});
    const NlsCoefficients top = coefficients(Params{1.5, 4.0 / 9, 1.0, rho}, Branch::optical, std::numbers::pi);
    BrightBreatherConfig c;
    c.model = &chain;
    c.kernels = sim::shipped_lattice_kernels("resonant_chain");
    c.omega_b = top.omega * 1.01;
    c.sites = 61;
    std::string message;
    try {
      validate(c);
    } catch (const InvalidParameter& e) {
      message = e.what();
    }
    CHECK(message.find("no focusing band edge") != std::string::npos);
    CHECK(message.find("optical at theta = pi: defocusing") != std::string::npos);
    CHECK(message.find("acoustic at theta = pi: defocusing") != std::string::npos);
  }
}

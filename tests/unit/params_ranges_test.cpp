// The declared ranges of the physical parameters (lrchain/params.hpp): the bounds themselves, and
// every value the paper, the examples and the report use lies inside them.
#include <doctest/doctest.h>

#include <filesystem>
#include <limits>

#include "lrchain/errors.hpp"
#include "lrchain/params.hpp"
#include "lrchain/jobs/experiment_config.hpp"
#include "lrchain/jobs/more_experiment_config.hpp"

namespace fs = std::filesystem;
using lrchain::Params;

namespace {

// The parameter validate(p) refuses, "" when it accepts p.
std::string refused(const Params& p) {
  try {
    lrchain::validate(p);
  } catch (const lrchain::InvalidParameter& e) {
    return e.parameter();
  }
  return "";
}

Params with(double alpha, double delta0, double kappa, double rho) { return Params{alpha, delta0, kappa, rho}; }

}  // namespace

TEST_CASE("params: each range's ends, inside and just outside") {
  const double inf = std::numeric_limits<double>::infinity(), nan = std::numeric_limits<double>::quiet_NaN();
  CHECK(refused(Params{}).empty());
  CHECK(refused(with(5.0, 4.0 / 9, 1, 1.0 / 3)).empty());   // alpha's upper end is inside
  CHECK(refused(with(1.0, 4.0 / 9, 1, 1.0 / 3)) == "alpha");  // its lower end is not
  CHECK(refused(with(5.0000001, 4.0 / 9, 1, 1.0 / 3)) == "alpha");
  CHECK(refused(with(1.5, 10.0, 1, 1.0 / 3)).empty());
  CHECK(refused(with(1.5, 10.000001, 1, 1.0 / 3)) == "delta0");
  CHECK(refused(with(1.5, 0.0, 1, 1.0 / 3)) == "delta0");
  CHECK(refused(with(1.5, 4.0 / 9, 1e4, 1e4)).empty());
  CHECK(refused(with(1.5, 4.0 / 9, 1.0001e4, 1)) == "kappa");
  CHECK(refused(with(1.5, 4.0 / 9, 1, 1.0001e4)) == "rho");
  CHECK(refused(with(1.5, 4.0 / 9, 1, 1e308)) == "rho");
  CHECK(refused(with(inf, 4.0 / 9, 1, 1)) == "alpha");
  CHECK(refused(with(1.5, nan, 1, 1)) == "delta0");
  CHECK_THROWS_WITH_AS(lrchain::validate(with(1.5, 4.0 / 9, 1, 1e308)),
                       "invalid rho: must be a finite number in (0, 10000] (mass ratio m2/m1 of resonator to bead); "
                       "got 1e+308",
                       lrchain::InvalidParameter);
  CHECK_NOTHROW(lrchain::check_in_range(1.0, lrchain::modulation_amplitude_range));
  CHECK_THROWS_AS(lrchain::check_in_range(1.01, lrchain::modulation_amplitude_range), lrchain::InvalidParameter);
  CHECK_NOTHROW(lrchain::check_drive_amplitude(4.0 / 9, 4.0 / 9));
  CHECK_THROWS_AS(lrchain::check_drive_amplitude(0.45, 4.0 / 9), lrchain::InvalidParameter);
}

TEST_CASE("params: the paper's, the regime maps' and the report's parameter values lie inside the ranges") {
  // Sec. 2-5 and the figure captions: rho 0.1, 0.32, 1/3, 1, 3, 10, 17.8; delta0 0.27, 4/9; the
  // regime maps' default axes: rho in [0.01, 30], delta0 in [0.001, 1]; alpha 3/2, kappa 1.
  for (double rho : {0.01, 0.1, 0.32, 1.0 / 3, 1.0, 3.0, 10.0, 17.8, 30.0})
    for (double delta0 : {0.001, 0.002, 0.06, 0.22, 0.27, 4.0 / 9, 1.0}) CHECK(refused(with(1.5, delta0, 1, rho)).empty());
  // Every example config loads (its values inside every range).
  int examples = 0;
  for (const auto& e : fs::directory_iterator(fs::path(LRCHAIN_SOURCE_DIR) / "examples")) {
    if (e.path().extension() != ".toml") continue;
    CAPTURE(e.path().filename().string());
    const std::string kind = lrchain::jobs::experiment_kind(e.path());
    if (kind == "bright") CHECK_NOTHROW(lrchain::jobs::load_experiment_config(e.path()));
    if (kind == "drive") CHECK_NOTHROW(lrchain::jobs::load_drive_config(e.path()));
    if (kind == "modulated") CHECK_NOTHROW(lrchain::jobs::load_modulated_config(e.path()));
    ++examples;
  }
  CHECK(examples == 9);
}

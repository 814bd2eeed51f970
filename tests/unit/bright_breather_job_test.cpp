// The exact bright-breather job through the library (lrchain/jobs/bright_breather_job.hpp).
#include <doctest/doctest.h>

#include <cmath>
#include <cstdio>

#include "lrchain/errors.hpp"
#include "lrchain/jobs/bright_breather_job.hpp"
#include "lrchain/model.hpp"
#include "lrchain/sim/model_lattice.hpp"

using namespace lrchain;
using namespace lrchain::jobs::bright_breather;

namespace {
struct Lattice {
  Model model;
  const lrchain_lattice_kernels* kernels;
  Lattice(const char* name, std::vector<std::pair<std::string, double>> values = {})
      : model(shipped_model(name, values)), kernels(sim::shipped_lattice_kernels(name)) {}
  BrightBreatherConfig config(BrightStep step, double omega_b, Index sites) const {
    BrightBreatherConfig c;
    c.step = step;
    c.model = &model;
    c.kernels = kernels;
    c.omega_b = omega_b;
    c.sites = sites;
    return c;
  }
};
}  // namespace

TEST_CASE("bright explore" * doctest::test_suite("fast")) {
  auto show = [](const Lattice& l, double omega_b, Index sites, const char* centre) {
    auto c = l.config(BrightStep::floquet, omega_b, sites);
    c.center = centre;
    try { validate(c); } catch (const std::exception& e) { std::printf("refused: %s\n", e.what()); return; }
    const auto r = run(c);
    auto j = to_json(r);
    j.erase("provenance"); j.erase("model"); if (j.contains("floquet")) j["floquet"].erase("multipliers");
    std::printf("%s %s %g %s\n", l.model.name().c_str(), centre, omega_b, j.dump().c_str());
  };
  const Lattice kg("klein_gordon");
  for (double d : {0.01, 0.005, 0.0025}) show(kg, 1.1832159566199232 + d, 121, "site");
  show(kg, 1.19, 61, "bond");
  const Lattice soft("klein_gordon", {{"b", -0.5}, {"a", 0}});
  show(soft, 0.97, 61, "site");
  show(soft, 0.97, 61, "bond");
  const Lattice fpu("fput");
  show(fpu, 2.05, 61, "site");
  show(fpu, 2.05, 61, "bond");
  const Lattice rc("resonant_chain");
  show(rc, 2.5, 61, "site");
  const Lattice dia("diatomic_chain");
  show(dia, 1.5, 61, "site");
}

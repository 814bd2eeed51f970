// models/resonant_chain.toml declares the same parameter ranges as the library's one table of
// physical ranges (lrchain/params.hpp), which the CLI options and the simulate configs use.
#include <doctest/doctest.h>

#include <filesystem>

#include "lrchain/derivation/model_file.hpp"
#include "lrchain/params.hpp"

TEST_CASE("resonant_chain.toml: [parameters] ranges equal lrchain's physical ranges of alpha, delta0, kappa, rho") {
  const auto model = lrchain::derivation::load_model_file(std::filesystem::path(LRCHAIN_SOURCE_DIR) / "models" /
                                                          "resonant_chain.toml");
  int matched = 0;
  for (const lrchain::PhysicalRange& lib : lrchain::model_parameter_ranges()) {
    CAPTURE(lib.name);
    for (const auto& p : model.parameters) {
      if (p.name != lib.name) continue;
      ++matched;
      REQUIRE(p.range.has_lower);
      REQUIRE(p.range.has_upper);
      CHECK(p.range.lower.to_double() == lib.min);
      CHECK(p.range.upper.to_double() == lib.max);
      CHECK(p.range.lower_closed == !lib.min_open);
      CHECK(p.range.upper_closed == !lib.max_open);
    }
  }
  CHECK(matched == 4);
}

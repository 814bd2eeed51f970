// Strain sites counted as 2N + 1 (strain_sites.hpp).
#include "lrchain/sim/strain_sites.hpp"

#include <fmt/format.h>

#include <limits>

#include "lrchain/errors.hpp"

namespace lrchain::sim {

namespace {
// InvalidParameter("sites") stating what `range` allows and the value given (`got`).
[[noreturn]] void refuse_sites(StrainSiteRange range, const std::string& got) {
  throw InvalidParameter("sites", fmt::format("must be an odd integer in [{}, {}]: the sites are n = -N..N, "
                                              "2N + 1 of them (got {})", range.least, range.most, got));
}
}  // namespace

Index strain_half_width(std::int64_t sites, StrainSiteRange range) {
  if (sites < range.least || sites > range.most || sites % 2 == 0) refuse_sites(range, std::to_string(sites));
  return Index((sites - 1) / 2);
}

void check_half_width(Index half_width, StrainSiteRange range) {
  if (half_width >= (range.least - 1) / 2 && half_width <= (range.most - 1) / 2) return;
  const bool count_fits = half_width > std::numeric_limits<Index>::min() / 2 && half_width < std::numeric_limits<Index>::max() / 2;
  refuse_sites(range, count_fits ? std::to_string(strain_site_count(half_width)) : fmt::format("N = {}", half_width));
}

}  // namespace lrchain::sim

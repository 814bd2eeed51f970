// Strain sites counted as 2N + 1 (strain_sites.hpp).
#include "lrchain/sim/strain_sites.hpp"

#include <fmt/format.h>

#include "lrchain/errors.hpp"

namespace lrchain::sim {

std::string strain_sites_rule(StrainSiteRange range, std::int64_t got) {
  return fmt::format("must be an odd integer in [{}, {}]: the strain sites are n = -N..N, 2N + 1 of them (got {})",
                     range.least, range.most, got);
}

Index strain_half_width(std::int64_t sites, StrainSiteRange range) {
  if (sites < range.least || sites > range.most || sites % 2 == 0)
    throw InvalidParameter("sites", strain_sites_rule(range, sites));
  return Index((sites - 1) / 2);
}

}  // namespace lrchain::sim

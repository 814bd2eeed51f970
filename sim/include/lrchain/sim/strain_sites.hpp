#pragma once
// The strain sites n = -N..N of a bright-breather run as the user counts them: sites = 2N + 1, an
// odd number (the command's --sites, the configs' [bright] sites, Python's sites=). The run
// configurations (BrightRunConfig, ModelBrightConfig) keep the half-width N.
#include <cstdint>
#include <string>

#include "lrchain/index.hpp"

namespace lrchain::sim {

// The allowed numbers of strain sites [least, most], both odd.
struct StrainSiteRange {
  std::int64_t least = 0, most = 0;
};
// The resonant chain's bright run: N in [2, 1e15], so that 2N + 2 beads stay far from overflow.
inline constexpr StrainSiteRange bright_sites{5, 2'000'000'000'000'001};
// A model file's bright run: N in [10, 5e7].
inline constexpr StrainSiteRange model_bright_sites{21, 100'000'001};

// The note of a config's old key N (the half-width), refused as renamed: "... use 'sites', <note>".
inline constexpr const char* half_width_renamed_note = "the number of strain sites 2N + 1 (the old N was the half-width)";

// sites = 2N + 1 of the half-width N.
constexpr std::int64_t strain_site_count(Index half_width) { return 2 * std::int64_t(half_width) + 1; }

// The half-width N = (sites - 1)/2; InvalidParameter("sites", "must be an odd integer in [5,
// 2000000000000001]: the strain sites are n = -N..N, 2N + 1 of them (got 4)") unless sites is odd
// and in `range`.
Index strain_half_width(std::int64_t sites, StrainSiteRange range);

// The same refusal for a run configured by its half-width N (2N + 1 may not fit an integer).
void check_half_width(Index half_width, StrainSiteRange range);

}  // namespace lrchain::sim

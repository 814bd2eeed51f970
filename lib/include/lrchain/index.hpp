#pragma once
// The integer type of the public API: site labels n, counts of sites, samples and iterations, and
// positions in arrays. Signed, because site labels run negative (n = -N..N) and labels, counts and
// their differences mix in one expression. Arrays of doubles cross the API as views whose size is
// their count: std::span<const double> to read, std::span<double> to write (the caller owns the
// storage); a function that sizes its result returns or fills a std::vector<double>.
#include <cstddef>

namespace lrchain {

using Index = std::ptrdiff_t;

}  // namespace lrchain

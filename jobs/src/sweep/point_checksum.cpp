// One point's record checksum (point_checksum.hpp).
#include "point_checksum.hpp"

#include <bit>
#include <cstdint>
#include <string>

namespace lrchain::jobs::sweep {

using namespace lrchain::sim;  // the numerics this job layer runs

namespace {

// Appends the little-endian bytes of a 64-bit value.
void put_u64(std::string& out, std::uint64_t v) {
  for (int k = 0; k < 8; ++k) out += char((v >> (8 * k)) & 0xFF);
}

void put_double(std::string& out, double v) { put_u64(out, std::bit_cast<std::uint64_t>(v)); }

}  // namespace

Sha256Digest point_checksum(const SweepResults& r, std::size_t point) {
  std::string index, numbers, rows;
  put_u64(index, point);
  put_double(numbers, r.wall_seconds[point]);
  for (std::size_t s = 0; s < r.scalar_names.size(); ++s) put_double(numbers, r.scalars[s * r.points + point]);
  if (!r.rows.empty())
    for (double v : r.rows[point]) put_double(rows, v);
  Sha256Builder b;
  b.field("lrchain sweep point record 1").field(index).field(std::string(1, char(r.status[point]))).field(numbers);
  b.field(r.reasons[point]).field(rows);
  return b.digest();
}

}  // namespace lrchain::jobs::sweep

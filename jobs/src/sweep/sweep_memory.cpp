// A sweep's memory from its sizes (sweep/sweep_memory.hpp).
#include "lrchain/jobs/sweep/sweep_memory.hpp"

#include <cstdint>
#include <cstdlib>
#include <string>
#include <vector>

#include "lrchain/sha256.hpp"

namespace lrchain::jobs::sweep {


double sweep_point_bytes(const SweepMemorySizes& s) {
  // In memory (SweepResults): scalars, status, wall time, the reason's string, the checksum, the
  // rows' vector and values; the point's index in the to-do list.
  const double record = 8 * s.scalars + 1 + 8 + double(sizeof(std::string)) + double(sizeof(Sha256Digest)) +
                        (s.row_columns > 0 ? double(sizeof(std::vector<double>)) + 8 * s.row_columns * s.rows_per_point : 0) +
                        8;
  // A write gathers the reasons' pointers and each row column; a read holds every reason string
  // (HDF5 allocates each, at least 32 bytes), the stored checksums and the rows once more.
  const double buffers = 8 + 32 + double(sizeof(Sha256Digest)) + 1 + (8 + 8 * s.row_columns + 8) * s.rows_per_point;
  return record + buffers;
}

double sweep_memory_bytes(const SweepMemorySizes& s) {
  return s.points * sweep_point_bytes(s) + s.ranks_on_node * 8 * s.axis_values;
}

int launcher_ranks_on_this_node() {
  for (const char* name : {"OMPI_COMM_WORLD_LOCAL_SIZE", "MPI_LOCALNRANKS"}) {
    if (const char* v = std::getenv(name)) {
      char* end = nullptr;
      const long n = std::strtol(v, &end, 10);
      if (end != v && *end == '\0' && n >= 1 && n <= 1'000'000) return int(n);
    }
  }
  return 1;
}

}  // namespace lrchain::jobs::sweep

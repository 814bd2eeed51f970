#pragma once
// The memory of a sweep, estimated from its sizes before anything is allocated: the results kept by
// rank 0 (one record per point: scalars, status, wall time, reason, checksum, rows, and the buffers
// of a results-file write and read) plus, per rank on that node, the axes' values.
#include <cstddef>

namespace lrchain::jobs::sweep {

struct SweepMemorySizes {
  double points = 0;          // grid or list points
  double scalars = 0;         // summary scalars per point
  double row_columns = 0;     // columns of the job's rows (0: none)
  double rows_per_point = 0;  // the most rows a point can give
  double axis_values = 0;     // values of all axes together
  double ranks_on_node = 1;   // MPI ranks on the node of rank 0 (1 without MPI)
};

// Bytes of one point's record with its share of the write and read buffers.
double sweep_point_bytes(const SweepMemorySizes& s);
// Peak bytes on the node of rank 0.
double sweep_memory_bytes(const SweepMemorySizes& s);

// The number of ranks on this node as the MPI launcher tells it in the environment (Open MPI's
// OMPI_COMM_WORLD_LOCAL_SIZE, MPICH's MPI_LOCALNRANKS); 1 when started without one.
int launcher_ranks_on_this_node();

}  // namespace lrchain::jobs::sweep

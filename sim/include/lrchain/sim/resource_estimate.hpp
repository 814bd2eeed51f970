#pragma once
// Memory and output size of a job, estimated from its options before anything is allocated or
// written, and the check that refuses a job that does not fit (InvalidParameter -> exit 2):
// the memory this process may use (the smallest of MemAvailable, RLIMIT_AS and the cgroup limit:
// available_memory) or an explicit --max-memory,
// and the free space of the output directory's file system.
#include <filesystem>
#include <string>
#include <vector>

#include "lrchain/index.hpp"
#include "lrchain/sim/integrator_options.hpp"

namespace lrchain::sim {

struct ResourceEstimate {
  double memory_bytes = 0;  // peak memory of the job
  double output_bytes = 0;  // files written to the output directory
  std::string sizes;        // what the estimate grows with, e.g. "N = 1e+09 sites, 801 samples"
  std::string dominant;     // the size that makes most of the memory (dark: sites, period, periods)
};

// Sizes of a lattice run (bright, drive, modulated) that its memory and output grow with.
struct LatticeRunSizes {
  double sites = 0;             // lattice sites (beads) integrated
  double observations = 0;      // observation times = rows of the series
  double series_columns = 5;    // columns of the series
  double spacetime_rows = 0;    // rows of the energy-density space-time field
  double snapshots = 0;         // snapshot profiles (6 columns per site)
  StepperKind stepper = StepperKind::rkf78;
};
ResourceEstimate estimate_lattice_run(const LatticeRunSizes& s);
// True when fewer sites save more memory than fewer samples: then a refusal names the lattice
// size rather than the sampling options.
bool lattice_dominates(const LatticeRunSizes& s);

// Sample intervals floor(duration / sample_every) of a run sampled on a regular grid, refused
// (InvalidParameter naming `duration_parameter`) when the count overflows any memory.
Index sample_intervals(double duration, double sample_every, const std::string& duration_parameter);
// The sizes of a run on a regular sample grid with space-time rows every `spacetime_every`.
LatticeRunSizes sampled_run_sizes(double sites, double duration, double sample_every, double spacetime_every,
                                  double snapshots, StepperKind stepper, const std::string& duration_parameter);
// The observation times a run keeps: the user's `given` ones as they are; of the `defaults`, those
// inside a run of length `end` (later ones are for a longer run).
std::vector<double> times_inside_run(const std::vector<double>& given, const std::vector<double>& defaults,
                                     double end);

// Exact dark breathers on `sites` sites: Newton/Floquet matrices, the recorded orbit of one
// shooting interval of `shooting_time`, and for an evolution `periods` stroboscopic snapshots.
ResourceEstimate estimate_dark_breather(double sites, bool floquet, double shooting_time,
                                        double periods);

// Exact breathers on the matrix-free path (dark/newton_krylov.hpp, dark/krylov_floquet.hpp) of
// `positions` unknowns: the band-probed Jacobian and its sparse LU (fill ~ 20 x its fields x (2 band + 1)
// entries per row), batches of 16 tangents with Runge-Kutta-Fehlberg 7(8)'s 13 stages, the GMRES and
// Arnoldi bases (`krylov_vectors` of 2 positions each).
ResourceEstimate estimate_krylov_breather(double positions, double fields, double band, double krylov_vectors);

// A regime map of `pixels` pixels in `panels` panels (CSV text, pixel values, boundary curves).
ResourceEstimate estimate_regime_map(double pixels, double panels);

// The memory this process may still allocate and what limits it.
struct MemoryLimit {
  double bytes = 0;    // 0: unknown (nothing could be read)
  std::string source;  // "available memory (MemAvailable)", "the address-space limit RLIMIT_AS ...", ...
};
// Where the limits are read (tests point these at files of their own).
struct MemorySources {
  std::filesystem::path meminfo = "/proc/meminfo";
  std::filesystem::path process_status = "/proc/self/status";   // VmSize, VmData: in use now
  std::filesystem::path process_cgroup = "/proc/self/cgroup";
  std::filesystem::path cgroup_root = "/sys/fs/cgroup";          // v2 here (or in unified/), v1 in memory/
};
// The smallest of: MemAvailable; RLIMIT_AS minus the address space in use (VmSize); RLIMIT_DATA
// minus the data segment (VmData); the cgroup v2 memory.max minus memory.current (or v1
// memory.limit_in_bytes minus memory.usage_in_bytes) of this process's group and of each group
// above it. Limits that are unset ("max", RLIM_INFINITY) do not count.
MemoryLimit available_memory(const MemorySources& sources);
// available_memory(MemorySources{}).bytes: 0 when nothing can be read.
double available_memory_bytes();

// Bytes free for an unprivileged user on the file system that holds `dir` (or, if it does not
// exist yet, its nearest existing parent); -1 when unknown.
double available_disk_bytes(const std::filesystem::path& dir);

// "2G", "500M", "1.5T", "64k", "4096" (bytes; binary units, K/M/G/T, optional trailing B/iB)
// -> bytes. Throws InvalidParameter(option) for anything else or a size < 1 MiB.
double parse_memory_size(const std::string& text, const std::string& option);

// Refuses the job (InvalidParameter(parameter)) when its memory exceeds `max_memory_bytes`
// (> 0) or, when that is 0, the machine's available memory. `advice` says what to lower.
void check_memory(const ResourceEstimate& e, double max_memory_bytes, const std::string& parameter,
                  const std::string& advice);

// Refuses the job when its output would not fit on the file system of `out_dir`.
void check_output_space(const ResourceEstimate& e, const std::filesystem::path& out_dir,
                        const std::string& parameter, const std::string& advice);

// A byte count for a message: "48 GB", "512 MB", "12 kB" (powers of 1000, 2 significant digits).
std::string format_bytes(double bytes);

}  // namespace lrchain::sim

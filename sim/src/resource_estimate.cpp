// Memory and output-size estimates of a job from its options, and the checks against the machine
// (resource_estimate.hpp). Every formula is an upper estimate of the dominant terms, in bytes.
#include "lrchain/sim/resource_estimate.hpp"

#include <sys/resource.h>
#include <sys/statvfs.h>

#include <cctype>
#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <fstream>
#include <optional>
#include <tuple>
#include <sstream>
#include <string>

#include "lrchain/checked_number.hpp"
#include "lrchain/errors.hpp"

namespace lrchain::sim {

namespace {

// State-sized vectors a stepper keeps besides the state (Odeint's stage and error storage).
double stepper_copies(StepperKind k) {
  switch (k) {
    case StepperKind::rkf78: return 18;   // 13 stages + temporary, derivative, error, new state
    case StepperKind::dopri5: return 14;  // 7 stages + dense-output pair of states and derivatives
    default: return 4;                    // symplectic RKN: positions/momenta copies, force buffer
  }
}

}  // namespace

ResourceEstimate estimate_lattice_run(const LatticeRunSizes& s) {
  ResourceEstimate e;
  const double state = 32 * s.sites;                           // 4 doubles per site (u, v, rates)
  const double series_text = 24 * s.series_columns * s.observations;  // ~24 characters per value
  const double snapshot_text = 24 * 6 * s.sites;                     // one snapshot CSV
  e.memory_bytes = state * (1 + stepper_copies(s.stepper))    // the state and the stepper's vectors
                   + 8 * 12 * s.sites                          // observer and force scratch
                   + 4 * (s.sites + 1) * s.spacetime_rows      // space-time field, float32 rows
                   + 8 * (s.series_columns + 1) * s.observations  // series rows, observation times
                   + 8 * 6 * s.sites * s.snapshots             // snapshot profiles
                   + std::max(series_text, snapshot_text);     // the largest CSV text being written
  e.output_bytes = 4 * (s.sites + 1) * (s.spacetime_rows + 1)  // space-time binary matrix
                   + series_text                                 // series.csv
                   + snapshot_text * s.snapshots                 // snapshot_*.csv
                   + 2e6;                                        // summary, scripts, figures
  e.sizes = fmt::format("{:.4g} sites, {:.4g} samples, {:.4g} space-time rows, {:.4g} snapshots",
                        s.sites, s.observations, s.spacetime_rows, s.snapshots);
  return e;
}

bool lattice_dominates(const LatticeRunSizes& s) {
  // The lever that saves more: ten times fewer sites, or ten times fewer samples and rows.
  LatticeRunSizes fewer_sites = s, fewer_samples = s;
  fewer_sites.sites /= 10;
  fewer_samples.observations /= 10;
  fewer_samples.spacetime_rows /= 10;
  return estimate_lattice_run(fewer_sites).memory_bytes <= estimate_lattice_run(fewer_samples).memory_bytes;
}

ResourceEstimate estimate_dark_breather(double sites, bool floquet, double shooting_time,
                                        double periods) {
  ResourceEstimate e;
  const double n = sites;
  // Newton: bases, tangent columns, Jacobian and its QR: ~24 n^2 doubles; Floquet adds the 4n x 4n
  // propagator, its copies for the reduction and the eigenvalue solver: ~64 n^2 more.
  const double matrices = 8 * (floquet ? 88.0 : 24.0) * n * n;
  // Recorded orbit of one shooting interval for the variational equations: 13 stages x n
  // stiffnesses per step, at most ~40 steps per time unit (max step 0.25, graded at contacts).
  const double record = 8 * 13 * n * (40 * shooting_time + 2000);
  const double evolution = 8 * 2 * n * (periods + 1)  // stroboscopic snapshots Z(m T_b)
                           + 2 * 4 * (n + 1) * (periods + 1);  // the two float32 fields written
  e.memory_bytes = matrices + record + evolution + 64 * 4 * n;
  e.dominant = matrices >= record && matrices >= evolution ? "sites" : record >= evolution ? "period" : "periods";
  e.output_bytes = 2 * 4 * (n + 1) * (periods + 1)  // x/y space-time binaries
                   + 24 * 6 * (periods + n)          // evolution.csv, profile/snapshot CSVs
                   + 2e6;                            // branch tables, scripts, figures
  e.sizes = fmt::format("{:.4g} sites{}", n,
                        periods > 0 ? fmt::format(", {:.4g} periods", periods) : std::string());
  return e;
}

ResourceEstimate estimate_krylov_breather(double positions, double fields, double band, double krylov_vectors) {
  ResourceEstimate e;
  const double lu = 8 * 20 * positions * fields * (2 * band + 1);
  const double tangents = 8 * 14 * 17 * 2 * positions;
  e.memory_bytes = lu + tangents + 8 * krylov_vectors * 2 * positions + 64 * 4 * positions;
  e.dominant = "sites";
  e.output_bytes = 24 * 6 * positions + 2e6;
  e.sizes = fmt::format("{:.4g} positions (matrix-free)", positions);
  return e;
}

ResourceEstimate estimate_regime_map(double pixels, double panels) {
  ResourceEstimate e;
  // Per panel: one byte per pixel, its CSV text (~36 characters per "x,y,regime" row) twice (the
  // stream and its string); panels are computed one after the other.
  e.memory_bytes = pixels * (1 + 2 * 36) + 50e6;
  e.output_bytes = 36 * pixels * panels + 2e6;
  e.sizes = fmt::format("{:.4g} pixels per panel, {:.0f} panel(s)", pixels, panels);
  return e;
}

namespace {

// The first number in `file` (a cgroup or /proc value); nullopt when missing or not a number
// ("max", cgroup v2's no limit).
std::optional<double> number_in(const std::filesystem::path& file) {
  std::ifstream in(file);
  double value = 0;
  if (!(in >> value)) return std::nullopt;
  return value;
}

// "Key:   123 kB" of /proc/self/status (or meminfo) in bytes; nullopt when absent.
std::optional<double> kib_entry(const std::filesystem::path& file, const std::string& key) {
  std::ifstream in(file);
  std::string name, unit;
  double value = 0;
  while (in >> name >> value) {
    std::getline(in, unit);
    if (name == key) return value * 1024;  // reported in kB (KiB)
  }
  return std::nullopt;
}

// The smaller of `best` and `candidate` (a missing candidate leaves best unchanged).
void keep_smaller(MemoryLimit& best, std::optional<double> candidate, const char* source) {
  if (!candidate) return;
  const double bytes = std::max(1.0, *candidate);  // (0 would read as "unknown")
  if (best.bytes <= 0 || bytes < best.bytes) best = {bytes, source};
}

// Headroom limit - usage of the cgroup directories at `root` + `path` and each parent up to root
// (a limit may be set on an ancestor; inside a container the root is the container's own group).
std::optional<double> cgroup_headroom(const std::filesystem::path& root, const std::string& path,
                                      const char* limit_file, const char* usage_file) {
  std::optional<double> least;
  std::filesystem::path relative = std::filesystem::path(path).relative_path();
  while (true) {
    const std::filesystem::path dir = root / relative;
    const auto limit = number_in(dir / limit_file);
    const auto usage = number_in(dir / usage_file);
    // cgroup v1 writes "no limit" as a page-rounded 2^63 - 1.
    if (limit && usage && *limit < 4.0e18 && (!least || *limit - *usage < *least)) least = *limit - *usage;
    if (relative.empty() || relative == relative.parent_path()) break;
    relative = relative.parent_path();
  }
  return least;
}

}  // namespace

MemoryLimit available_memory(const MemorySources& sources) {
  MemoryLimit best;
  keep_smaller(best, kib_entry(sources.meminfo, "MemAvailable:"), "available memory (MemAvailable)");
  // Address-space and data-segment limits (ulimit -v, ulimit -d) less what the process uses now.
  for (const auto& [resource, usage_key, source] :
       {std::tuple{RLIMIT_AS, "VmSize:", "the address-space limit RLIMIT_AS (ulimit -v)"},
        std::tuple{RLIMIT_DATA, "VmData:", "the data-segment limit RLIMIT_DATA (ulimit -d)"}}) {
    struct rlimit limit {};
    if (::getrlimit(resource, &limit) != 0 || limit.rlim_cur == RLIM_INFINITY) continue;
    const double used = kib_entry(sources.process_status, usage_key).value_or(0);
    keep_smaller(best, double(limit.rlim_cur) - used, source);
  }
  // The cgroup of this process: "0::/path" (v2), "N:memory:/path" or "N:...,memory,...:/path" (v1).
  std::ifstream groups(sources.process_cgroup);
  for (std::string line; std::getline(groups, line);) {
    const auto first = line.find(':'), second = line.find(':', first + 1);
    if (first == std::string::npos || second == std::string::npos) continue;
    const std::string controllers = line.substr(first + 1, second - first - 1), path = line.substr(second + 1);
    if (line.compare(0, first, "0") == 0 && controllers.empty()) {
      for (const auto& root : {sources.cgroup_root, sources.cgroup_root / "unified"})
        keep_smaller(best, cgroup_headroom(root, path, "memory.max", "memory.current"),
                     "the cgroup memory limit (memory.max)");
    } else if (("," + controllers + ",").find(",memory,") != std::string::npos) {
      keep_smaller(best, cgroup_headroom(sources.cgroup_root / "memory", path, "memory.limit_in_bytes",
                                         "memory.usage_in_bytes"),
                   "the cgroup memory limit (memory.limit_in_bytes)");
    }
  }
  return best;
}

double available_memory_bytes() { return available_memory(MemorySources{}).bytes; }

double available_disk_bytes(const std::filesystem::path& dir) {
  std::filesystem::path p = dir.empty() ? std::filesystem::path(".") : dir;
  std::error_code ec;
  while (!std::filesystem::exists(p, ec)) {
    if (!p.has_parent_path() || p.parent_path() == p) {
      p = ".";
      break;
    }
    p = p.parent_path();
  }
  struct statvfs fs {};
  if (::statvfs(p.c_str(), &fs) != 0) return -1;
  return double(fs.f_bavail) * double(fs.f_frsize);
}

double parse_memory_size(const std::string& text, const std::string& option) {
  const auto fail = [&]() -> double {
    throw InvalidParameter(option, "expected a size such as 2G, 500M or 1.5T (at least 1M), got '" +
                                       text + "'");
  };
  std::size_t used = 0;
  double value = 0;
  try {
    value = std::stod(text, &used);
  } catch (const std::exception&) {
    return fail();
  }
  std::string unit = text.substr(used);
  if (!unit.empty() && (unit.back() == 'B' || unit.back() == 'b')) unit.pop_back();
  if (unit.size() == 2 && unit[1] == 'i') unit.pop_back();
  double scale = 1;
  if (unit.size() == 1) {
    switch (std::toupper(static_cast<unsigned char>(unit[0]))) {
      case 'K': scale = 1024.0; break;
      case 'M': scale = 1024.0 * 1024; break;
      case 'G': scale = 1024.0 * 1024 * 1024; break;
      case 'T': scale = 1024.0 * 1024 * 1024 * 1024; break;
      default: return fail();
    }
  } else if (!unit.empty()) {
    return fail();
  }
  const double bytes = value * scale;
  if (!std::isfinite(bytes) || bytes < 1024.0 * 1024) return fail();
  return bytes;
}

std::string format_bytes(double bytes) {
  const char* units[] = {"bytes", "kB", "MB", "GB", "TB", "PB", "EB"};
  int u = 0;
  while (bytes >= 1000 && u < 6) {
    bytes /= 1000;
    ++u;
  }
  if (u == 6 && bytes >= 1000) return fmt::format("{:.2g} EB", bytes);
  return fmt::format("{:.{}f} {}", bytes, bytes < 10 && u > 0 ? 1 : 0, units[u]);
}

void check_memory(const ResourceEstimate& e, double max_memory_bytes, const std::string& parameter,
                  const std::string& advice) {
  if (max_memory_bytes > 0) {
    if (e.memory_bytes > max_memory_bytes)
      throw InvalidParameter(parameter, fmt::format("the job needs about {} of memory ({}), more than "
                                                    "--max-memory {}; {} or raise --max-memory",
                                                    format_bytes(e.memory_bytes), e.sizes,
                                                    format_bytes(max_memory_bytes), advice));
    return;
  }
  const MemoryLimit available = available_memory(MemorySources{});
  if (available.bytes > 0 && e.memory_bytes > available.bytes)
    throw InvalidParameter(parameter, fmt::format("the job needs about {} of memory ({}); this process "
                                                  "may use {} ({}); {} or pass --max-memory",
                                                  format_bytes(e.memory_bytes), e.sizes,
                                                  format_bytes(available.bytes), available.source, advice));
}

void check_output_space(const ResourceEstimate& e, const std::filesystem::path& out_dir,
                        const std::string& parameter, const std::string& advice) {
  const double free = available_disk_bytes(out_dir);
  if (free >= 0 && e.output_bytes > free)
    throw InvalidParameter(parameter, fmt::format("the job writes about {} ({}) but the file system "
                                                  "of '{}' has {} free; {}",
                                                  format_bytes(e.output_bytes), e.sizes,
                                                  out_dir.string(), format_bytes(free), advice));
}

Index sample_intervals(double duration, double sample_every, const std::string& duration_parameter) {
  constexpr Index max_samples = 1'000'000'000'000'000;  // far above any memory; no overflow
  return checked_count(std::floor(duration / sample_every + 1e-9), duration_parameter, 1, max_samples,
                       "samples (" + duration_parameter + " / sample-every)");
}

LatticeRunSizes sampled_run_sizes(double sites, double duration, double sample_every, double spacetime_every,
                                  double snapshots, StepperKind stepper, const std::string& duration_parameter) {
  LatticeRunSizes s;
  s.sites = sites;
  s.observations = double(sample_intervals(duration, sample_every, duration_parameter)) + 2 + snapshots;
  s.series_columns = 5;
  s.spacetime_rows = std::floor(duration / spacetime_every) + 1;
  s.snapshots = snapshots;
  s.stepper = stepper;
  return s;
}

std::vector<double> times_inside_run(const std::vector<double>& given, const std::vector<double>& defaults,
                                     double end) {
  if (given != defaults) return given;
  std::vector<double> inside;
  for (double t : given)
    if (t <= end * (1 + 1e-12)) inside.push_back(t);
  return inside;
}

}  // namespace lrchain::sim

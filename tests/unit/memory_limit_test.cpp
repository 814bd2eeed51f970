// The memory a job may use is the smallest of MemAvailable, RLIMIT_AS (less the address space in
// use) and the cgroup limit (v2 memory.max - memory.current, v1 memory.limit_in_bytes -
// memory.usage_in_bytes, of the process's group or any group above it). Before, only MemAvailable
// counted: a 9.4 GB job under a 6 GB RLIMIT_AS was accepted and died with bad_alloc after 50 s.
#include <doctest/doctest.h>

#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>

#include "../support/run_lrchain.hpp"
#include "lrchain/sim/resource_estimate.hpp"

namespace fs = std::filesystem;
using namespace lrchain::sim;

namespace {

void put(const fs::path& file, const std::string& text) {
  fs::create_directories(file.parent_path());
  std::ofstream(file) << text;
}

// A fake /proc and /sys/fs/cgroup under `root`, MemAvailable 8 GiB.
MemorySources fake_sources(const fs::path& root, const std::string& cgroup_lines) {
  MemorySources s;
  s.meminfo = root / "meminfo";
  s.process_status = root / "status";
  s.process_cgroup = root / "cgroup";
  s.cgroup_root = root / "sys";
  put(s.meminfo, "MemTotal:       16777216 kB\nMemAvailable:    8388608 kB\n");
  put(s.process_status, "VmSize:   100000 kB\nVmData:    50000 kB\n");
  put(s.process_cgroup, cgroup_lines);
  return s;
}

}  // namespace

TEST_CASE("available_memory: the cgroup v2 limit of the group or a group above it, less its usage") {
  const fs::path root = fs::temp_directory_path() / ("lrchain-memory-v2-" + std::to_string(::getpid()));
  fs::remove_all(root);
  const MemorySources s = fake_sources(root, "0::/user.slice/job\n");
  CHECK(available_memory(s).bytes == 8388608.0 * 1024);  // no cgroup files yet: MemAvailable
  CHECK(available_memory(s).source.find("MemAvailable") != std::string::npos);
  put(s.cgroup_root / "user.slice/job/memory.max", "max\n");  // no limit on the job's own group
  put(s.cgroup_root / "user.slice/job/memory.current", "123\n");
  put(s.cgroup_root / "user.slice/memory.max", "3000000000\n");  // 3 GB on its parent, 1 GB used
  put(s.cgroup_root / "user.slice/memory.current", "1000000000\n");
  const MemoryLimit m = available_memory(s);
  CHECK(m.bytes == 2e9);
  CHECK(m.source.find("memory.max") != std::string::npos);
  fs::remove_all(root);
}

TEST_CASE("available_memory: cgroup v1 memory.limit_in_bytes, also where the group's path is not mounted (a container)") {
  const fs::path root = fs::temp_directory_path() / ("lrchain-memory-v1-" + std::to_string(::getpid()));
  fs::remove_all(root);
  const MemorySources s = fake_sources(root, "5:devices:/\n4:memory:/process_api/abc\n0::/\n");
  put(s.cgroup_root / "memory/memory.limit_in_bytes", "1500000000\n");
  put(s.cgroup_root / "memory/memory.usage_in_bytes", "500000000\n");
  CHECK(available_memory(s).bytes == 1e9);
  put(s.cgroup_root / "memory/memory.limit_in_bytes", "9223372036854771712\n");  // v1's "no limit"
  CHECK(available_memory(s).bytes == 8388608.0 * 1024);
  fs::remove_all(root);
}

TEST_CASE("CLI: a 9.4 GB bright run under a 6 GB RLIMIT_AS is exit 2 naming --sites, at once") {
  using namespace lrchain::test;
  if (!lrchain::program_in_path("prlimit")) return;  // util-linux
#ifdef LRCHAIN_SANITIZE_BUILD
  return;  // AddressSanitizer's shadow memory cannot be mapped under a 6 GB RLIMIT_AS (the Release build runs this)
#endif
  // 10.3e6 strain sites: ~9.3 GB by estimate_lattice_run (rkf78: ~900 bytes a site).
  const auto r = run_command({"prlimit", "--as=6000000000", "--", LRCHAIN_CLI, "simulate", "bright", "--branch", "optical",
                              "--theta", "pi/2", "--sites", "10300001", "--periods", "1", "--stepper", "rkf78"});
  CHECK(r.exit_code == 2);
  CHECK(r.err.find("invalid sites") != std::string::npos);
  CHECK(r.err.find("RLIMIT_AS") != std::string::npos);
  CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
}

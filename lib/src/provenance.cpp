// Provenance of results (provenance.hpp): build facts from CMake and the build-time git commit,
// machine and invocation facts read at run time.
#include "lrchain/provenance.hpp"

#include <ctime>
#include <fstream>
#include <iterator>
#include <thread>

#include "lrchain_git_commit.h"  // generated at build time by cmake/git_commit.cmake

#ifndef LRCHAIN_COMPILER
#define LRCHAIN_COMPILER ""
#endif
#ifndef LRCHAIN_BUILD_TYPE
#define LRCHAIN_BUILD_TYPE ""
#endif

namespace lrchain {

BuildInfo build_info() {
  return {LRCHAIN_VERSION_STRING, LRCHAIN_GIT_COMMIT, LRCHAIN_COMPILER, LRCHAIN_BUILD_TYPE};
}

namespace {

// argv of this process from /proc/self/cmdline (NUL-separated); empty where there is no /proc.
std::vector<std::string> own_command_line() {
  std::ifstream in("/proc/self/cmdline", std::ios::binary);
  const std::string raw((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::vector<std::string> args;
  std::size_t start = 0;
  for (std::size_t i = 0; i < raw.size(); ++i)
    if (raw[i] == '\0') args.push_back(raw.substr(start, i - start)), start = i + 1;
  if (start < raw.size()) args.push_back(raw.substr(start));
  return args;
}

std::string utc_now() {
  const std::time_t t = std::time(nullptr);
  std::tm utc{};
  gmtime_r(&t, &utc);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", &utc);
  return buf;
}

}  // namespace

Provenance current_provenance() {
  return {build_info(), static_cast<Index>(std::thread::hardware_concurrency()), utc_now(), own_command_line()};
}

std::string version_line() {
  const BuildInfo b = build_info();
  return "lrchain " + b.version + " (commit " + (b.commit.empty() ? std::string("unknown") : b.commit) + ")";
}

}  // namespace lrchain

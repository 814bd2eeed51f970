#pragma once
// A scratch directory for one test, with XDG_CACHE_HOME pointing at its "cache" (the model cache is
// then <dir>/cache/lrchain); the previous XDG_CACHE_HOME is restored and the directory removed after.
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <string>

namespace lrchain::test {

struct ScratchCache {
  std::filesystem::path dir;
  std::string old_cache;
  explicit ScratchCache(const std::string& prefix) {
    dir = std::filesystem::temp_directory_path() /
          (prefix + "-" + std::to_string(::getpid()) + "-" + std::to_string(std::rand()));
    std::filesystem::create_directories(dir);
    if (const char* c = std::getenv("XDG_CACHE_HOME")) old_cache = c;
    ::setenv("XDG_CACHE_HOME", (dir / "cache").c_str(), 1);
  }
  ~ScratchCache() {
    if (old_cache.empty()) ::unsetenv("XDG_CACHE_HOME");
    else ::setenv("XDG_CACHE_HOME", old_cache.c_str(), 1);
    std::error_code ec;
    std::filesystem::permissions(dir / "cache", std::filesystem::perms::owner_all, ec);
    std::filesystem::remove_all(dir, ec);
  }
  std::filesystem::path cache() const { return dir / "cache" / "lrchain"; }
};

}  // namespace lrchain::test

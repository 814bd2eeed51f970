#pragma once
// The per-user cache of compiled model objects ($XDG_CACHE_HOME/lrchain, docs/models.md), verified
// before anything in it is loaded: the directory is ours and writable by nobody else, and an entry
// is an object plus a manifest (written atomically after the compile) that records the object's
// SHA-256. Anything else at an entry (a changed, truncated, empty or foreign object, a directory,
// a missing or garbled manifest) is a cache miss, never loaded.
#include <atomic>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

namespace lrchain {

// $XDG_CACHE_HOME/lrchain (an absolute XDG_CACHE_HOME), else $HOME/.cache/lrchain.
std::filesystem::path model_cache_directory();

// One entry: `<directory>/<stem>.manifest` names the object `<stem>.<first 16 hex digits of its
// SHA-256>.so`, and holds the 64 hex digits of that SHA-256.
struct CacheEntry {
  std::filesystem::path directory;
  std::string stem;  // prefix + the 64 hex digits of the cache key
};

// dlopen handle of the entry's object when the cache directory and the entry pass every check,
// nullptr on a miss; `library` is set to the object's path either way (the entry's stem when there
// is none). Throws InputError naming the directory when the cache is not safe to use (owned by
// another user, or writable by group or others).
void* open_verified_object(const CacheEntry& entry, std::filesystem::path* library);

// Whether the entry has an object that passes the checks (without loading it).
bool has_verified_object(const CacheEntry& entry);

// The compiler ran and failed: its exit status and the tail of its stderr, in one line.
struct CompilerFailed : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// One translation unit of a compiled model: its source text and the compiler options it needs.
struct CompileUnit {
  std::string source;
  std::vector<std::string> options;  // e.g. {"-O2"}
};

// Compiles every unit with `compiler` (one process each, all at once, `-c`) and links them into a
// fresh object of the entry (unique temporary names, then renamed into place with its manifest),
// after removing the temporaries that dead processes left behind. Each compiler runs in a process
// group of its own; once `stop` is set every group is killed, the temporaries removed and
// lrchain::Interrupted (SIGINT) thrown. Throws InputError for an unsafe cache directory or something
// other than a file at the entry's manifest (both before compiling), CompilerFailed when the
// compiler fails, std::runtime_error when the cache cannot be written.
void compile_into_entry(const std::vector<CompileUnit>& units, const std::string& compiler, const CacheEntry& entry,
                        const std::string& what, const std::atomic<bool>* stop = nullptr);

// Removes `.model-PID-*` temporaries of `directory` whose process PID no longer runs; returns how many.
int remove_stale_temporaries(const std::filesystem::path& directory);

}  // namespace lrchain

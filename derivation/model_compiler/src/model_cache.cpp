#include "model_cache.hpp"

#include <dlfcn.h>
#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <memory>
#include <optional>
#include <random>
#include <stdexcept>

#include "lrchain/errors.hpp"
#include "lrchain/process.hpp"
#include "lrchain/sha256.hpp"

namespace fs = std::filesystem;

namespace lrchain {

namespace {

constexpr std::size_t kMaxObjectBytes = std::size_t(256) << 20;  // far above any emitted model

// Closes a descriptor on every path out.
class Descriptor {
 public:
  explicit Descriptor(int fd = -1) : fd_(fd) {}
  Descriptor(Descriptor&& other) noexcept : fd_(other.fd_) { other.fd_ = -1; }
  Descriptor& operator=(Descriptor&& other) noexcept {
    std::swap(fd_, other.fd_);
    return *this;
  }
  ~Descriptor() {
    if (fd_ >= 0) ::close(fd_);
  }
  int get() const { return fd_; }
  explicit operator bool() const { return fd_ >= 0; }

 private:
  int fd_;
};

std::string octal_mode(mode_t mode) {
  char buffer[8];
  std::snprintf(buffer, sizeof buffer, "%04o", unsigned(mode & 07777));
  return buffer;
}

// The parent of the cache (XDG_CACHE_HOME or ~/.cache), when it exists: ours or root's, and not
// world-writable unless ours (else another user could have put the cache directory there).
void check_cache_parent(const fs::path& parent) {
  struct stat s{};
  if (::stat(parent.c_str(), &s) != 0) return;  // created (as ours) when the first model is compiled
  if (s.st_uid != ::geteuid() && s.st_uid != 0)
    throw InputError("the model cache's directory " + parent.string() + " belongs to another user (uid " +
                     std::to_string(s.st_uid) + "); set XDG_CACHE_HOME to a directory of your own");
  if ((s.st_mode & S_IWOTH) && s.st_uid != ::geteuid())
    throw InputError("the model cache's directory " + parent.string() + " is writable by every user and not yours (mode " +
                     octal_mode(s.st_mode) + "); set XDG_CACHE_HOME to a directory of your own");
}

// An open cache directory: a directory of ours that neither group nor others can write.
void check_cache_directory(int fd, const fs::path& directory) {
  struct stat s{};
  if (::fstat(fd, &s) != 0 || !S_ISDIR(s.st_mode))
    throw InputError("the model cache " + directory.string() + " is not a directory; delete it or set XDG_CACHE_HOME");
  if (s.st_uid != ::geteuid())
    throw InputError("the model cache " + directory.string() + " belongs to another user (uid " + std::to_string(s.st_uid) +
                     "); set XDG_CACHE_HOME to a directory of your own");
  if (s.st_mode & (S_IWGRP | S_IWOTH))
    throw InputError("the model cache " + directory.string() + " is writable by group or others (mode " +
                     octal_mode(s.st_mode) + "); run chmod go-w on it or set XDG_CACHE_HOME to a directory of your own");
}

// The cache directory, checked; with `create`, made (mode 0700) when missing, else an empty
// descriptor when missing.
Descriptor open_cache_directory(bool create) {
  const fs::path directory = model_cache_directory();
  check_cache_parent(directory.parent_path());
  if (create) {
    std::error_code ec;
    fs::create_directories(directory.parent_path(), ec);
    if (ec) throw std::runtime_error("cannot create the model cache " + directory.string() + ": " + ec.message());
    if (::mkdir(directory.c_str(), 0700) != 0 && errno != EEXIST)
      throw std::runtime_error("cannot create the model cache " + directory.string() + ": " + std::strerror(errno));
  }
  Descriptor fd(::open(directory.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC));
  if (!fd) {
    if (!create && (errno == ENOENT)) return fd;
    throw InputError("the model cache " + directory.string() + " cannot be opened as a directory (" + std::strerror(errno) +
                     "); delete it or set XDG_CACHE_HOME");
  }
  check_cache_directory(fd.get(), directory);
  return fd;
}

// A file of the cache opened without following links: a regular file of ours that neither group
// nor others can write, of 1 to `max_bytes` bytes; else an empty descriptor.
Descriptor open_cache_file(int directory, const std::string& name, std::size_t max_bytes, std::size_t* size) {
  Descriptor fd(::openat(directory, name.c_str(), O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_NOCTTY | O_CLOEXEC));
  if (!fd) return fd;
  struct stat s{};
  if (::fstat(fd.get(), &s) != 0 || !S_ISREG(s.st_mode) || s.st_uid != ::geteuid() || (s.st_mode & (S_IWGRP | S_IWOTH)) ||
      s.st_size <= 0 || std::size_t(s.st_size) > max_bytes)
    return Descriptor();
  *size = std::size_t(s.st_size);
  return fd;
}

// SHA-256 (hex) of what `fd` holds from its start, or nullopt when it cannot be read in full.
std::optional<std::string> content_sha256(int fd, std::size_t size, std::string* bytes = nullptr) {
  Sha256Builder hash;
  std::vector<char> buffer(1 << 16);
  std::size_t total = 0;
  for (;;) {
    const ssize_t n = ::pread(fd, buffer.data(), buffer.size(), off_t(total));
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) return std::nullopt;
    if (n == 0) break;
    hash.raw(buffer.data(), std::size_t(n));
    if (bytes) bytes->append(buffer.data(), std::size_t(n));
    total += std::size_t(n);
  }
  if (total != size) return std::nullopt;
  return hash.hex();
}

bool is_sha256_hex(const std::string& text) {
  return text.size() == 64 && text.find_first_not_of("0123456789abcdef") == std::string::npos;
}

std::string object_name(const CacheEntry& entry, const std::string& object_sha256) {
  return entry.stem + "." + object_sha256.substr(0, 16) + ".so";
}

// The entry's object, opened and checked against its manifest; an empty descriptor on a miss.
Descriptor verified_object(int directory, const CacheEntry& entry, std::string* name) {
  std::size_t size = 0;
  const Descriptor manifest = open_cache_file(directory, entry.stem + ".manifest", 65, &size);
  if (!manifest) return Descriptor();
  std::string recorded;
  if (!content_sha256(manifest.get(), size, &recorded)) return Descriptor();
  if (!recorded.empty() && recorded.back() == '\n') recorded.pop_back();
  if (!is_sha256_hex(recorded)) return Descriptor();
  *name = object_name(entry, recorded);
  Descriptor object = open_cache_file(directory, *name, kMaxObjectBytes, &size);
  if (!object) return Descriptor();
  const auto actual = content_sha256(object.get(), size);
  if (!actual || *actual != recorded) return Descriptor();
  return object;
}

// Writes `text` to a new file `name` of `directory` (mode 0644; fails if it exists).
void write_new_file(int directory, const std::string& name, const std::string& text, const fs::path& shown) {
  Descriptor fd(::openat(directory, name.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0644));
  if (!fd) throw std::runtime_error("cannot write " + shown.string() + ": " + std::strerror(errno));
  std::size_t written = 0;
  while (written < text.size()) {
    const ssize_t n = ::write(fd.get(), text.data() + written, text.size() - written);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) throw std::runtime_error("cannot write " + shown.string() + ": " + std::strerror(errno));
    written += std::size_t(n);
  }
}

// Removes the entry's objects other than `keep` (superseded; a process that loaded one keeps its mapping).
void remove_superseded_objects(const fs::path& directory, const CacheEntry& entry, const std::string& keep) {
  std::error_code ec;
  for (fs::directory_iterator it(directory, ec), end; !ec && it != end; it.increment(ec)) {
    const std::string name = it->path().filename().string();
    if (name != keep && name.rfind(entry.stem + ".", 0) == 0 && name.size() > 3 &&
        name.compare(name.size() - 3, 3, ".so") == 0 && it->is_regular_file(ec))
      fs::remove(it->path(), ec);
  }
}

// "exit status 1" or "killed by signal 9".
std::string exit_status_text(const ProcessResult& r) {
  return r.exited ? "exit status " + std::to_string(r.exit_code) : "killed by signal " + std::to_string(r.signal_number);
}

// The last lines of a compiler's stderr as one line of at most ~400 printable characters.
std::string stderr_tail(const std::string& text) {
  std::string line;
  for (const char c : text) {
    const bool printable = static_cast<unsigned char>(c) >= 0x20 && c != 0x7f;
    if (printable) line += c;
    else if (!line.empty() && line.back() != ' ') line += ' ';
  }
  while (!line.empty() && line.back() == ' ') line.pop_back();
  if (line.empty()) return "it wrote nothing on stderr";
  constexpr std::size_t kShown = 400;
  return "stderr ends: " + (line.size() > kShown ? "..." + line.substr(line.size() - kShown) : line);
}

// Before compiling: the entry's manifest path holds a regular file or nothing (a directory or
// anything else there would make the compile's result unplaceable, and leave its object behind).
void check_manifest_path(int directory, const CacheEntry& entry) {
  struct stat s{};
  const std::string name = entry.stem + ".manifest";
  if (::fstatat(directory, name.c_str(), &s, AT_SYMLINK_NOFOLLOW) != 0) return;
  if (!S_ISREG(s.st_mode))
    throw InputError("the model cache entry " + (entry.directory / name).string() +
                     " is not a regular file; delete it (lrchain recompiles the model)");
}

}  // namespace

fs::path model_cache_directory() {
  const char* xdg = std::getenv("XDG_CACHE_HOME");
  if (xdg && *xdg && fs::path(xdg).is_absolute()) return fs::path(xdg) / "lrchain";
  const char* home = std::getenv("HOME");
  if (!home || !*home) throw std::runtime_error("cannot place the model cache: neither XDG_CACHE_HOME nor HOME is set");
  return fs::path(home) / ".cache" / "lrchain";
}

void* open_verified_object(const CacheEntry& entry, fs::path* library) {
  if (library) *library = entry.directory / entry.stem;
  const Descriptor directory = open_cache_directory(false);
  if (!directory) return nullptr;
  std::string name;
  const Descriptor object = verified_object(directory.get(), entry, &name);
  if (!object) return nullptr;
  if (library) *library = entry.directory / name;
  // By its path (a /proc/self/fd/N name would be taken by dlopen for an earlier object that had the
  // same descriptor number): only this user can change the directory between the check and the load.
  return ::dlopen((entry.directory / name).c_str(), RTLD_NOW | RTLD_LOCAL);
}

bool has_verified_object(const CacheEntry& entry) {
  const Descriptor directory = open_cache_directory(false);
  std::string name;
  return directory && verified_object(directory.get(), entry, &name);
}

int remove_stale_temporaries(const fs::path& directory) {
  int removed = 0;
  std::error_code ec;
  for (fs::directory_iterator it(directory, ec), end; !ec && it != end; it.increment(ec)) {
    const std::string name = it->path().filename().string();
    if (name.rfind(".model-", 0) != 0) continue;
    const std::size_t start = 7, stop = name.find('-', start);
    if (stop == std::string::npos || stop == start || name.find_first_not_of("0123456789", start) != stop) continue;
    const long pid = std::strtol(name.c_str() + start, nullptr, 10);
    if (pid <= 0 || pid == ::getpid() || ::kill(pid_t(pid), 0) == 0 || errno != ESRCH) continue;
    std::error_code removal;
    if (!it->is_directory(removal) && fs::remove(it->path(), removal)) ++removed;
  }
  return removed;
}

// Runs the compiler with `argv` (after the compiler's path) in a process group of its own.
static std::unique_ptr<ChildProcess> start_compiler(const std::string& compiler, std::vector<std::string> argv, const std::atomic<bool>* stop) {
  ProcessOptions process;
  process.capture_stderr = true;
  process.own_process_group = true;  // a stop kills the driver and its cc1plus, as
  process.stop = stop;
  argv.insert(argv.begin(), compiler);
  return std::make_unique<ChildProcess>(argv, process);
}

void compile_into_entry(const std::vector<CompileUnit>& units, const std::string& compiler, const CacheEntry& entry,
                        const std::string& what, const std::atomic<bool>* stop) {
  const Descriptor directory = open_cache_directory(true);
  check_manifest_path(directory.get(), entry);
  remove_stale_temporaries(entry.directory);
  std::random_device random;
  const std::string stem = ".model-" + std::to_string(::getpid()) + "-" + std::to_string(random());
  const fs::path object = entry.directory / (stem + ".so");
  std::vector<fs::path> temporaries;  // the units' sources and objects
  std::error_code ec;
  const auto remove_temporaries = [&] {
    for (const fs::path& t : temporaries) fs::remove(t, ec);
  };
  // Whatever way this returns or throws (a unit that cannot be written, a failed compile, a stop),
  // the units' files and the unplaced object go (once placed, the object is no longer at `object`).
  struct RemoveOnExit {
    const std::function<void()> remove;
    ~RemoveOnExit() { remove(); }
  } remove_on_exit{[&] {
    std::error_code ignored;
    for (const fs::path& t : temporaries) fs::remove(t, ignored);
    fs::remove(object, ignored);
  }};
  const auto failed = [&](const ProcessResult& r, const std::string& step) {
    remove_temporaries();
    fs::remove(object, ec);
    if (r.stopped) throw Interrupted(SIGINT, "stopped while compiling " + what + "; nothing was cached");
    throw CompilerFailed("the C++ compiler " + compiler + " failed " + step + " " + what + " (" + exit_status_text(r) +
                         "; " + stderr_tail(r.error_output) + ")");
  };
  // Every unit compiled at once (one process each), then linked into one shared object.
  std::vector<std::string> link{"-shared", "-o", object.string()};
  std::vector<std::unique_ptr<ChildProcess>> compiles;
  for (std::size_t i = 0; i < units.size(); ++i) {
    const std::string unit = stem + "." + std::to_string(i);
    const fs::path source = entry.directory / (unit + ".cpp"), unit_object = entry.directory / (unit + ".o");
    temporaries.push_back(source);
    temporaries.push_back(unit_object);
    write_new_file(directory.get(), unit + ".cpp", units[i].source, source);
    std::vector<std::string> argv{"-std=c++17"};
    argv.insert(argv.end(), units[i].options.begin(), units[i].options.end());
    argv.insert(argv.end(), {"-fPIC", "-c", "-o", unit_object.string(), source.string()});
    compiles.push_back(start_compiler(compiler, argv, stop));
    link.push_back(unit_object.string());
  }
  std::optional<ProcessResult> first_failure;
  for (auto& c : compiles) {  // every child waited for (a stop reaches each), the first failure reported
    const ProcessResult r = c->wait();
    if (!r.ok() && (!first_failure || (r.stopped && !first_failure->stopped))) first_failure = r;
  }
  if (first_failure) failed(*first_failure, "compiling");
  const ProcessResult linked = start_compiler(compiler, link, stop)->wait();
  if (!linked.ok()) failed(linked, "linking");
  remove_temporaries();
  const auto fail = [&](const std::string& why) {
    fs::remove(object, ec);
    throw std::runtime_error(why);
  };
  if (::fchmodat(directory.get(), (stem + ".so").c_str(), 0755, 0) != 0) fail("cannot set the mode of " + object.string());
  std::size_t size = 0;
  std::optional<std::string> digest;
  {
    const Descriptor compiled = open_cache_file(directory.get(), stem + ".so", kMaxObjectBytes, &size);
    if (compiled) digest = content_sha256(compiled.get(), size);
  }
  if (!digest) fail("the compiler wrote no readable object for " + what);
  const std::string name = object_name(entry, *digest);
  if (::renameat(directory.get(), (stem + ".so").c_str(), directory.get(), name.c_str()) != 0)
    fail("cannot place " + (entry.directory / name).string() + " in the model cache (" + std::strerror(errno) +
         "); delete what is at that path");
  // The manifest last, atomically: a reader sees the old entry or the complete new one.
  write_new_file(directory.get(), stem + ".manifest", *digest + "\n", entry.directory / (stem + ".manifest"));
  if (::renameat(directory.get(), (stem + ".manifest").c_str(), directory.get(), (entry.stem + ".manifest").c_str()) != 0) {
    const int rename_errno = errno;
    ::unlinkat(directory.get(), (stem + ".manifest").c_str(), 0);
    ::unlinkat(directory.get(), name.c_str(), 0);  // unreachable without its manifest
    throw InputError("cannot write the manifest " + (entry.directory / (entry.stem + ".manifest")).string() + " (" +
                     std::strerror(rename_errno) + "); delete what is at that path");
  }
  remove_superseded_objects(entry.directory, entry, name);
}

}  // namespace lrchain

// Reading a model file for any front end: a regular file of bounded size, opened without blocking
// (a FIFO or a device never hangs or floods the reader), and identifying a shipped one by SHA-256.
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "lrchain/errors.hpp"
#include "../files/file_kind.hpp"
#include "lrchain/model.hpp"
#include "lrchain/sha256.hpp"

namespace lrchain {

namespace {

// Closes a descriptor on every path out.
struct Descriptor {
  int fd;
  ~Descriptor() {
    if (fd >= 0) ::close(fd);
  }
};

}  // namespace

std::string read_model_file_bytes(const std::string& path) {
  const std::string allowed = "; a model file must be a regular file of at most " +
                              std::to_string(kMaxModelFileBytes >> 20) + " MiB";
  const Descriptor file{::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_NOCTTY | O_CLOEXEC)};
  if (file.fd < 0) throw InputError(path + ": cannot read the model file (" + std::strerror(errno) + ")");
  struct stat status{};
  if (::fstat(file.fd, &status) != 0) throw InputError(path + ": cannot read the model file (" + std::strerror(errno) + ")");
  if (!S_ISREG(status.st_mode)) throw InputError(path + ": " + file_kind_text(status.st_mode) + allowed);
  if (std::size_t(status.st_size) > kMaxModelFileBytes)
    throw InputError(path + ": " + std::to_string(status.st_size) + " bytes" + allowed);
  std::string bytes(kMaxModelFileBytes + 1, '\0');
  std::size_t size = 0;
  while (size < bytes.size()) {
    const ssize_t n = ::read(file.fd, bytes.data() + size, bytes.size() - size);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) throw InputError(path + ": cannot read the model file (" + std::strerror(errno) + ")");
    if (n == 0) break;
    size += std::size_t(n);
  }
  if (size > kMaxModelFileBytes) throw InputError(path + ": more than " + std::to_string(kMaxModelFileBytes) + " bytes" + allowed);
  bytes.resize(size);
  return bytes;
}

const ModelDefinition* find_shipped_model_by_sha256(std::string_view sha256) {
  for (const auto& m : shipped_models())
    if (!m.file_sha256.empty() && m.file_sha256 == sha256) return &m;
  return nullptr;
}

const ModelDefinition* find_shipped_model_by_bytes(std::string_view bytes) {
  return find_shipped_model_by_sha256(sha256_hex(bytes));
}

ModelFileContent read_model_file(const std::string& path) {
  ModelFileContent file{path, read_model_file_bytes(path), {}};
  file.sha256 = sha256_hex(file.bytes);
  return file;
}

}  // namespace lrchain

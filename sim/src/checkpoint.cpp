// Binary checkpoint files: "LRCKPT01", uint64 tag length, tag, uint64 size, double t, size doubles.
#include "lrchain/sim/checkpoint.hpp"

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <stdexcept>

namespace lrchain::sim {

namespace {
constexpr char kMagic[8] = {'L', 'R', 'C', 'K', 'P', 'T', '0', '1'};
}

void write_checkpoint(const std::filesystem::path& file, const Checkpoint& c) {
  const std::filesystem::path tmp = file.string() + ".tmp";
  {
    std::ofstream os(tmp, std::ios::binary | std::ios::trunc);
    if (!os) throw std::runtime_error("cannot write checkpoint '" + tmp.string() + "'");
    const std::uint64_t tag_len = c.tag.size(), n = c.state.size();
    os.write(kMagic, 8);
    os.write(reinterpret_cast<const char*>(&tag_len), sizeof tag_len);
    os.write(c.tag.data(), std::streamsize(tag_len));
    os.write(reinterpret_cast<const char*>(&n), sizeof n);
    os.write(reinterpret_cast<const char*>(&c.t), sizeof c.t);
    os.write(reinterpret_cast<const char*>(c.state.data()), std::streamsize(n * sizeof(double)));
    os.flush();
    if (!os) throw std::runtime_error("cannot write checkpoint '" + tmp.string() + "'");
  }
  std::filesystem::rename(tmp, file);
}

Checkpoint read_checkpoint(const std::filesystem::path& file) {
  std::ifstream is(file, std::ios::binary);
  if (!is) throw std::runtime_error("cannot open checkpoint '" + file.string() + "'");
  auto fail = [&] { return std::runtime_error("malformed checkpoint '" + file.string() + "'"); };
  char magic[8];
  if (!is.read(magic, 8) || !std::equal(magic, magic + 8, kMagic)) throw fail();
  std::uint64_t tag_len = 0, n = 0;
  if (!is.read(reinterpret_cast<char*>(&tag_len), sizeof tag_len) || tag_len > 4096) throw fail();
  Checkpoint c;
  c.tag.resize(tag_len);
  if (!is.read(c.tag.data(), std::streamsize(tag_len))) throw fail();
  if (!is.read(reinterpret_cast<char*>(&n), sizeof n) || n > (1ull << 32)) throw fail();
  if (!is.read(reinterpret_cast<char*>(&c.t), sizeof c.t)) throw fail();
  c.state.resize(n);
  if (!is.read(reinterpret_cast<char*>(c.state.data()), std::streamsize(n * sizeof(double))))
    throw fail();
  return c;
}

}  // namespace lrchain::sim

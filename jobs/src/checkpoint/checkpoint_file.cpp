// Checkpoint files, format 3 (layout in checkpoint_file.hpp): writer, verifying reader, identity check.
//
// The file checksum is Boost.CRC's crc_32_type (the CRC of zip and PNG): it detects every error
// burst up to 32 bits and every odd number of flipped bits, which a multiplicative hash such as
// FNV does not guarantee; accidental corruption (a torn copy, a flipped bit) is what it must catch.
// The identity and initial-state hashes are SHA-256 (lrchain/sha256.hpp, OpenSSL's libcrypto): a
// checkpoint is continued only by the run it was written for, and no crafted file can pass for
// another run's. Format 2 (FNV-1a 64 fingerprints, lrchain 0.1) is refused with a message saying so.
#include "lrchain/jobs/checkpoint/checkpoint_file.hpp"

#include <boost/crc.hpp>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fmt/format.h>
#include <fstream>
#include <limits>
#include <stdexcept>
#include <type_traits>

#include "lrchain/errors.hpp"
#include "lrchain/output_target.hpp"
#include "lrchain/sha256.hpp"
#include "lrchain/jobs/output_files.hpp"

namespace lrchain::jobs {

namespace fs = std::filesystem;
using sim::Snapshot;
using sim::SpaceTime;

namespace {

constexpr char kMagic[8] = {'L', 'R', 'C', 'K', 'P', 'T', '\r', '\n'};
constexpr std::uint32_t kFormatVersion = 3;
constexpr std::uint64_t kMaxText = 1u << 20;  // identity and progress texts are a few hundred bytes

// Appends the bytes of trivially copyable values and length-prefixed arrays to a buffer.
struct Writer {
  std::string bytes;
  template <class T>
  void put(const T& v) {
    static_assert(std::is_trivially_copyable_v<T>);
    bytes.append(reinterpret_cast<const char*>(&v), sizeof v);
  }
  void put_string(const std::string& s) {
    put(std::uint64_t(s.size()));
    bytes += s;
  }
  template <class T>
  void put_array(const std::vector<T>& v) {
    put(std::uint64_t(v.size()));
    bytes.append(reinterpret_cast<const char*>(v.data()), v.size() * sizeof(T));
  }
  void put_strings(const std::vector<std::string>& v) {
    put(std::uint64_t(v.size()));
    for (const auto& s : v) put_string(s);
  }
};

// Reads from the checkpoint file; every length is checked against the bytes left before anything
// is allocated, so a corrupted size can neither crash nor allocate more than the file holds.
struct Reader {
  std::ifstream in;
  std::uint64_t left;  // bytes left before the CRC trailer
  fs::path file;

  [[noreturn]] void fail(const std::string& what) const {
    throw InputError("checkpoint '" + file.string() + "' is not a usable lrchain checkpoint: " + what);
  }
  void read_bytes(void* out, std::uint64_t n, const char* what) {
    if (n > left) fail(fmt::format("truncated ({} needs {} bytes, {} left)", what, n, left));
    if (!in.read(static_cast<char*>(out), std::streamsize(n))) fail(std::string("cannot read ") + what);
    left -= n;
  }
  template <class T>
  T get(const char* what) {
    T v;
    read_bytes(&v, sizeof v, what);
    return v;
  }
  std::uint64_t get_count(std::uint64_t element_size, const char* what) {
    const auto n = get<std::uint64_t>(what);
    if (n > left / element_size)
      fail(fmt::format("{} claims {} entries, more than the {} bytes left in the file", what, n, left));
    return n;
  }
  std::string get_string(const char* what, std::uint64_t max = kMaxText) {
    const std::uint64_t n = get_count(1, what);
    if (n > max) fail(fmt::format("{} is {} bytes long (at most {})", what, n, max));
    std::string s(n, '\0');
    read_bytes(s.data(), n, what);
    return s;
  }
  template <class T>
  std::vector<T> get_array(const char* what) {
    const std::uint64_t n = get_count(sizeof(T), what);
    std::vector<T> v(n);
    read_bytes(v.data(), n * sizeof(T), what);
    return v;
  }
  std::vector<std::string> get_strings(const char* what) {
    const std::uint64_t n = get_count(sizeof(std::uint64_t), what);
    std::vector<std::string> v;
    for (std::uint64_t i = 0; i < n; ++i) v.push_back(get_string(what));
    return v;
  }
};

void put_record(Writer& w, const RunRecord& r) {
  w.put_strings(r.series.names);
  w.put_array(r.series.data);
  w.put(std::uint64_t(r.fields.size()));
  for (const auto& f : r.fields) {
    w.put_string(f.quantity);
    w.put(std::int64_t(f.first_label));
    w.put(std::uint64_t(f.sites));
    w.put_array(f.times);
    w.put_array(f.values);
  }
  w.put(std::uint64_t(r.snapshots.size()));
  for (const auto& s : r.snapshots) {
    w.put(s.t);
    w.put_string(s.tag);
    w.put_strings(s.names);
    w.put_array(s.data);
  }
}

RunRecord get_record(Reader& r) {
  RunRecord rec;
  rec.series.names = r.get_strings("series names");
  rec.series.data = r.get_array<double>("series data");
  if (!rec.series.names.empty() && rec.series.data.size() % rec.series.names.size() != 0)
    r.fail("series rows are incomplete");
  const std::uint64_t fields = r.get_count(8 * 4, "field count");
  for (std::uint64_t k = 0; k < fields; ++k) {
    SpaceTime f;
    f.quantity = r.get_string("field name");
    f.first_label = long(r.get<std::int64_t>("field first label"));
    const std::uint64_t sites = r.get<std::uint64_t>("field sites");
    f.times = r.get_array<double>("field times");
    f.values = r.get_array<float>("field values");
    if (sites == 0 || f.values.size() / sites != f.times.size() || f.values.size() % sites != 0)
      r.fail("field rows do not match its times");
    f.sites = static_cast<Index>(sites);  // at most the number of values read
    rec.fields.push_back(std::move(f));
  }
  const std::uint64_t snapshots = r.get_count(8 * 4, "snapshot count");
  for (std::uint64_t k = 0; k < snapshots; ++k) {
    Snapshot s;
    s.t = r.get<double>("snapshot time");
    s.tag = r.get_string("snapshot tag");
    s.names = r.get_strings("snapshot names");
    s.data = r.get_array<double>("snapshot data");
    if (s.names.empty() || s.data.size() % s.names.size() != 0) r.fail("snapshot rows are incomplete");
    rec.snapshots.push_back(std::move(s));
  }
  return rec;
}

std::string hex_double(double v) { return fmt::format("{:a}", v); }

// "key = value" lines into pairs; false if a line is not of that form.
bool parse_lines(const std::string& text, std::vector<std::pair<std::string, std::string>>& out) {
  std::size_t pos = 0;
  while (pos < text.size()) {
    const std::size_t end = text.find('\n', pos);
    if (end == std::string::npos) return false;
    const std::string line = text.substr(pos, end - pos);
    const std::size_t eq = line.find(" = ");
    if (eq == std::string::npos || eq == 0) return false;
    out.emplace_back(line.substr(0, eq), line.substr(eq + 3));
    pos = end + 1;
  }
  return true;
}

// Exact double from hex text (as written by hex_double); false on anything else.
bool parse_double(const std::string& s, double& v) {
  if (s.empty()) return false;
  char* end = nullptr;
  v = std::strtod(s.c_str(), &end);
  return end == s.c_str() + s.size();
}

// CRC-32 of the first `n` bytes of the file, read in blocks (no whole-file buffer).
std::uint32_t file_crc(std::ifstream& in, std::uint64_t n) {
  boost::crc_32_type crc;
  std::vector<char> block(1 << 16);
  while (n > 0) {
    const std::size_t k = std::size_t(std::min<std::uint64_t>(n, block.size()));
    if (!in.read(block.data(), std::streamsize(k))) return ~crc.checksum();
    crc.process_bytes(block.data(), k);
    n -= k;
  }
  return crc.checksum();
}

}  // namespace

double Checkpoint::accumulator(const fs::path& file, const std::string& name) const {
  for (const auto& [k, v] : accumulators)
    if (k == name) return v;
  throw InputError("checkpoint '" + file.string() + "' lacks the run's value '" + name + "'");
}

void write_checkpoint(const fs::path& file, const Checkpoint& c, const RunRecord& record) {
  write_checkpoint(file, c.identity, {c.t, c.next_step, c.steps, c.rhs_evaluations, c.accumulators}, c.state, record);
}

void write_checkpoint(const fs::path& file, const std::string& identity, const sim::RunProgress& p,
                      const State& state, const RunRecord& record) {
  check_output_target(file);
  Writer w;
  w.bytes.append(kMagic, 8);
  w.put(kFormatVersion);
  w.put_string(identity);
  w.put(sha256(identity));
  std::string progress = "t = " + hex_double(p.t) + "\nnext_step = " + hex_double(p.next_step) +
                         "\nsteps = " + std::to_string(p.steps) +
                         "\nrhs_evaluations = " + std::to_string(p.rhs_evaluations) + "\n";
  for (const auto& [k, v] : p.accumulators) progress += k + " = " + hex_double(v) + "\n";
  w.put_string(progress);
  w.put_array(state);
  put_record(w, record);
  boost::crc_32_type crc;
  crc.process_bytes(w.bytes.data(), w.bytes.size());
  w.put(std::uint32_t(crc.checksum()));

  const fs::path tmp = jobs::temporary_name(file);
  {
    std::ofstream os(tmp, std::ios::binary | std::ios::trunc);
    os.write(w.bytes.data(), std::streamsize(w.bytes.size()));
    os.flush();
    if (!os) {
      std::error_code ec;
      fs::remove(tmp, ec);
      throw std::runtime_error("cannot write checkpoint '" + tmp.string() + "'");
    }
  }
  std::error_code ec;
  fs::rename(tmp, file, ec);
  if (ec) {
    fs::remove(tmp, ec);
    throw std::runtime_error("cannot write checkpoint '" + file.string() + "'");
  }
}

Checkpoint read_checkpoint(const fs::path& file) {
  std::error_code ec;
  if (!fs::is_regular_file(file, ec))
    throw InputError("checkpoint '" + file.string() + "' does not exist or is not a file");
  const std::uint64_t size = fs::file_size(file, ec);
  if (ec) throw InputError("cannot read checkpoint '" + file.string() + "'");
  Reader r{std::ifstream(file, std::ios::binary), 0, file};
  if (!r.in) throw InputError("cannot open checkpoint '" + file.string() + "'");
  constexpr std::uint64_t header = 8 + sizeof(std::uint32_t);
  if (size < header + sizeof(std::uint32_t)) r.fail(fmt::format("only {} bytes long", size));
  r.left = header;
  char magic[8];
  r.read_bytes(magic, 8, "magic");
  if (std::memcmp(magic, kMagic, 8) != 0) r.fail("no checkpoint magic at its start");
  const auto version = r.get<std::uint32_t>("format version");
  if (version == 2)
    r.fail("format version 2, written by lrchain 0.1 with FNV-1a fingerprints; this lrchain writes and reads "
           "version 3 (SHA-256) only: run again without --restart");
  if (version != kFormatVersion)
    r.fail(fmt::format("format version {} (this lrchain reads version {})", version, kFormatVersion));

  // Whole-file CRC before trusting any size inside it.
  r.in.seekg(0);
  const std::uint64_t body = size - sizeof(std::uint32_t);
  const std::uint32_t computed = file_crc(r.in, body);
  std::uint32_t stored = 0;
  if (!r.in.read(reinterpret_cast<char*>(&stored), sizeof stored) || stored != computed)
    r.fail("checksum mismatch (the file is truncated or corrupted)");
  r.in.seekg(std::streamoff(header));
  r.left = body - header;

  Checkpoint c;
  c.identity = r.get_string("identity");
  const auto identity_hash = r.get<Sha256Digest>("identity hash");
  if (identity_hash != sha256(c.identity)) r.fail("identity hash (SHA-256) mismatch");
  std::vector<std::pair<std::string, std::string>> items;
  if (!parse_lines(c.identity, items)) r.fail("malformed identity lines");
  const std::string progress = r.get_string("progress");
  items.clear();
  if (!parse_lines(progress, items)) r.fail("malformed progress lines");
  bool have_t = false, have_step = false;
  for (const auto& [k, v] : items) {
    double x = 0;
    if (!parse_double(v, x)) r.fail("progress value '" + k + "' is not a number");
    if (k == "t") { c.t = x; have_t = true; }
    else if (k == "next_step") { c.next_step = x; have_step = true; }
    else if (k == "steps") c.steps = std::strtoull(v.c_str(), nullptr, 10);
    else if (k == "rhs_evaluations") c.rhs_evaluations = std::strtoull(v.c_str(), nullptr, 10);
    else c.accumulators.emplace_back(k, x);
  }
  if (!have_t || !have_step) r.fail("no time or step size");
  if (!(std::isfinite(c.t) && c.t >= 0)) r.fail(fmt::format("time {} is not a finite number >= 0", c.t));
  if (!(std::isfinite(c.next_step) && c.next_step > 0)) r.fail("step size is not a finite number > 0");
  c.state = r.get_array<double>("state");
  for (std::size_t i = 0; i < c.state.size(); ++i)
    if (!std::isfinite(c.state[i])) r.fail(fmt::format("state entry {} is not finite", i));
  c.record = get_record(r);
  if (r.left != 0) r.fail(fmt::format("{} unexpected bytes after the record", r.left));
  return c;
}

void check_same_trajectory(const fs::path& file, const Checkpoint& c, const TrajectoryIdentity& run) {
  std::vector<std::pair<std::string, std::string>> stored;
  parse_lines(c.identity, stored);  // verified by read_checkpoint
  const std::string run_text = run.text();
  std::vector<std::pair<std::string, std::string>> current;
  parse_lines(run_text, current);
  for (const auto& [key, value] : current) {
    const std::string* old = nullptr;
    for (const auto& [k, v] : stored)
      if (k == key) old = &v;
    if (!old)
      throw InvalidParameter("restart", fmt::format("checkpoint '{}' does not record {} (it was written "
                                                    "for another kind of run)", file.string(), key));
    if (*old != value)
      throw InvalidParameter("restart", fmt::format("checkpoint '{}' was written with {}, this run has {}",
                                                    file.string(), run.shown(key, *old), run.shown(key, value)));
  }
  if (stored.size() != current.size())
    throw InvalidParameter("restart", fmt::format("checkpoint '{}' records {} items, this run {}",
                                                  file.string(), stored.size(), current.size()));
}

}  // namespace lrchain::jobs

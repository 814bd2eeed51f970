// The sweep's side files and their manifest (sweep/side_files.hpp).
#include "lrchain/jobs/sweep/side_files.hpp"

#include <fstream>
#include <map>
#include <sstream>

#include <nlohmann/json.hpp>

#include "lrchain/errors.hpp"
#include "lrchain/sha256.hpp"
#include "lrchain/jobs/output_files.hpp"
#include "lrchain/jobs/sweep/sweep_figure.hpp"

namespace lrchain::jobs::sweep {

using namespace lrchain::sim;  // the numerics this job layer runs

namespace fs = std::filesystem;

namespace {

constexpr const char* manifest_kind = "lrchain sweep side files";
constexpr const char* pending = "pending";

// name -> SHA-256 hex or "pending", from the manifest (empty when there is none); InputError
// when the manifest's name is taken by a file that is not one.
std::map<std::string, std::string> read_manifest(const SweepConfig& c) {
  const fs::path path = side_files_manifest(c);
  std::error_code ec;
  if (!fs::exists(fs::symlink_status(path, ec))) return {};
  const auto refuse = [&] {
    return InputError("'" + path.string() + "' is not the side-file list of an lrchain sweep; move it away or choose another output");
  };
  if (!fs::is_regular_file(fs::symlink_status(path, ec))) throw refuse();
  std::ifstream in(path);
  std::ostringstream text;
  text << in.rdbuf();
  const nlohmann::json j = nlohmann::json::parse(text.str(), nullptr, false);
  if (!j.is_object() || j.value("kind", "") != manifest_kind || !j.contains("files") || !j["files"].is_object())
    throw refuse();
  std::map<std::string, std::string> files;
  for (const auto& [name, hash] : j["files"].items())
    if (hash.is_string()) files[name] = hash.get<std::string>();
  return files;
}

void write_manifest(const SweepConfig& c, const std::map<std::string, std::string>& files) {
  nlohmann::json j;
  j["kind"] = manifest_kind;
  j["results"] = c.output.filename().string();
  j["files"] = files;
  ensure_directory(output_directory(c));
  write_file_atomic(output_directory(c), side_files_manifest(c).filename().string(), j.dump(2) + "\n");
}

// SHA-256 of a file's bytes (hex).
std::string file_sha256(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream bytes;
  bytes << in.rdbuf();
  return sha256_hex(bytes.str());
}

// Where a side file is, as the messages name it ("out/r.csv", or "r.csv" beside a bare output name).
fs::path side_file_path(const SweepConfig& c, const std::string& name) {
  return c.output.has_parent_path() ? c.output.parent_path() / name : fs::path(name);
}

}  // namespace

fs::path output_directory(const SweepConfig& c) {
  return c.output.has_parent_path() ? c.output.parent_path() : fs::path(".");
}

fs::path side_files_manifest(const SweepConfig& c) {
  return output_directory(c) / ("." + c.output.filename().string() + ".lrchain-files");
}

std::vector<std::string> csv_view_files(const SweepConfig& c, const Job& job) {
  if (c.points() > c.csv_max_points) return {};
  fs::path name = c.output.filename();
  std::vector<std::string> files{fs::path(name).replace_extension(".csv").string()};
  if (!job.row_names().empty()) files.push_back(name.replace_extension(".rows.csv").string());
  return files;
}

std::vector<std::string> sweep_side_files(const SweepConfig& c, const Job& job) {
  std::vector<std::string> files = csv_view_files(c, job);
  for (auto& f : sweep_figure_files(c)) files.push_back(std::move(f));
  return files;
}

void check_side_files(const SweepConfig& c, const Job& job) {
  const auto written = read_manifest(c);
  for (const auto& name : sweep_side_files(c, job)) {
    const fs::path path = side_file_path(c, name);
    std::error_code ec;
    if (!fs::exists(fs::symlink_status(path, ec))) continue;
    const auto it = written.find(name);
    const bool ours = it != written.end() && fs::is_regular_file(fs::symlink_status(path, ec)) &&
                      (it->second == pending || it->second == file_sha256(path));
    if (!ours)
      throw InputError("'" + path.string() + "' exists and was not written by this sweep" +
                       (it == written.end() ? "" : " (it changed since)") +
                       "; the sweep would replace it: move it away or choose another output");
  }
}

void mark_side_files_pending(const SweepConfig& c, const std::vector<std::string>& names) {
  if (names.empty()) return;
  auto files = read_manifest(c);
  for (const auto& n : names) files[n] = pending;
  write_manifest(c, files);
}

void record_side_files(const SweepConfig& c, const std::vector<std::string>& names) {
  if (names.empty()) return;
  auto files = read_manifest(c);
  for (const auto& n : names) {
    const fs::path path = side_file_path(c, n);
    std::error_code ec;
    if (fs::is_regular_file(fs::symlink_status(path, ec)))
      files[n] = file_sha256(path);
    else
      files.erase(n);
  }
  write_manifest(c, files);
}

}  // namespace lrchain::jobs::sweep

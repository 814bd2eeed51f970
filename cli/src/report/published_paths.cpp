// Paths in a finished report's JSON files (published_paths.hpp).
#include "published_paths.hpp"

#include <fstream>
#include <sstream>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "lrchain/jobs/output_files.hpp"

namespace lrchain::report {

namespace fs = std::filesystem;

namespace {

// `text` with every occurrence of the directory `from` (followed by '/' or the end) replaced by `to`.
std::string moved(const std::string& text, const std::string& from, const std::string& to) {
  std::string out;
  std::size_t i = 0;
  for (std::size_t hit; (hit = text.find(from, i)) != std::string::npos;) {
    const std::size_t end = hit + from.size();
    const bool whole = end == text.size() || text[end] == '/';
    out += text.substr(i, hit - i) + (whole ? to : from);
    i = end;
  }
  return out + text.substr(i);
}

// Rewrites the path fields of `j` in place; true if anything changed.
bool rewrite(nlohmann::ordered_json& j, const std::string& from, const std::string& to) {
  bool changed = false;
  const auto fix = [&](nlohmann::ordered_json& value) {
    if (!value.is_string()) return;
    const std::string now = moved(value.get<std::string>(), from, to);
    if (now != value.get<std::string>()) value = now, changed = true;
  };
  if (j.is_object()) {
    for (auto& [key, value] : j.items()) {
      if (key == "out" || key == "checkpoint_file") fix(value);
      if (key == "command_line") {
        if (value.is_array())
          for (auto& element : value) fix(element);
        else
          fix(value);
      }
      if (value.is_structured()) changed = rewrite(value, from, to) || changed;
    }
  } else if (j.is_array()) {
    for (auto& element : j) changed = rewrite(element, from, to) || changed;
  }
  return changed;
}

}  // namespace

void point_json_files_at(const fs::path& building, const fs::path& published) {
  const std::string from = building.string(), to = published.string();
  for (const auto& entry : fs::recursive_directory_iterator(building)) {
    if (!entry.is_regular_file() || entry.path().extension() != ".json") continue;
    std::ifstream in(entry.path());
    std::stringstream text;
    text << in.rdbuf();
    if (!in && !in.eof()) throw std::runtime_error("cannot read " + entry.path().string());
    if (text.str().find(from) == std::string::npos) continue;
    nlohmann::ordered_json j;
    try {
      j = nlohmann::ordered_json::parse(text.str());
    } catch (const std::exception& e) {
      throw std::runtime_error("invalid JSON in " + entry.path().string() + ": " + e.what());
    }
    if (rewrite(j, from, to))
      jobs::write_file_atomic(entry.path().parent_path(), entry.path().filename().string(), j.dump(2) + "\n");
  }
}

}  // namespace lrchain::report

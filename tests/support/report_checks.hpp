#pragma once
// Checks of a report written by `lrchain reproduce` (used by the fast and validation tests):
// every linked file exists, every fragment exists in its page, and headless Chromium renders
// index.html with every image loaded (the report marks each <img> data-load="ok"/"broken").
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "run_lrchain.hpp"

namespace lrchain::test {

inline std::string slurp(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// Links (href/src) of a page that do not resolve: missing files, or fragments with no such id.
inline std::vector<std::string> broken_links(const std::filesystem::path& page) {
  namespace fs = std::filesystem;
  std::vector<std::string> broken;
  const std::string html = slurp(page);
  const std::regex attr(R"re((?:href|src)="([^"]*)")re");
  for (std::sregex_iterator it(html.begin(), html.end(), attr), end; it != end; ++it) {
    const std::string link = (*it)[1];
    if (link.rfind("http://", 0) == 0 || link.rfind("https://", 0) == 0) {
      broken.push_back(link + " (external link in an offline report)");
      continue;
    }
    const auto hash = link.find('#');
    const std::string file = link.substr(0, hash);
    const fs::path target = file.empty() ? page : page.parent_path() / file;
    if (!fs::exists(target)) {
      broken.push_back(link + " (no such file)");
      continue;
    }
    if (hash != std::string::npos) {
      const std::string id = link.substr(hash + 1);
      if (slurp(target).find("id=\"" + id + "\"") == std::string::npos) broken.push_back(link + " (no such id)");
    }
  }
  return broken;
}

struct BrowserResult {
  bool ran = false;
  int images = 0, loaded = 0, broken = 0;
  std::string dom;
};

// Renders the page in headless Chromium and counts the images it marked loaded / broken.
inline BrowserResult render_in_chromium(const std::filesystem::path& page, const std::filesystem::path& profile) {
  BrowserResult r;
  CommandResult run;
  try {
    run = run_command({"chromium", "--headless", "--no-sandbox", "--disable-gpu", "--disable-dev-shm-usage",
                       "--disable-background-networking", "--no-first-run", "--user-data-dir=" + profile.string(),
                       "--virtual-time-budget=15000", "--dump-dom",
                       "file://" + std::filesystem::absolute(page).string()});
  } catch (const std::exception&) {  // chromium not installed
    return r;
  }
  r.dom = run.out;
  r.ran = run.exit_code == 0 && !r.dom.empty();
  auto count = [&](const std::string& what) {
    int n = 0;
    for (std::size_t p = 0; (p = r.dom.find(what, p)) != std::string::npos; p += what.size()) ++n;
    return n;
  };
  r.images = count("<img ");
  r.loaded = count("data-load=\"ok\"");
  r.broken = count("data-load=\"broken\"");
  return r;
}

}  // namespace lrchain::test

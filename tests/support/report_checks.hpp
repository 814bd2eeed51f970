#pragma once
// Checks of a report written by `lrchain reproduce` (used by the fast and validation tests):
// every linked file exists, every fragment exists in its page, headless Chromium renders the
// pages with every image loaded (the report marks each <img> data-load="ok"/"broken"), every
// table has one column count, and no page names a directory of the build.
#include <filesystem>
#include <fstream>
#include <cctype>
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

// The bodies of the elements <tag ...>body</tag> in html, in order (no nesting of the same tag).
// A plain scan: std::regex with [\s\S]*? recurses once per character and overflows the stack on a
// rendered page (seen under AddressSanitizer).
inline std::vector<std::string> element_bodies(const std::string& html, const std::string& tag) {
  std::vector<std::string> bodies;
  const std::string open = "<" + tag, close = "</" + tag + ">";
  for (std::size_t p = 0; (p = html.find(open, p)) != std::string::npos;) {
    const std::size_t after = p + open.size();
    if (after >= html.size() || (html[after] != '>' && !std::isspace(static_cast<unsigned char>(html[after])))) {
      p = after;  // <tbody>, <thead>, <track>: a longer tag name
      continue;
    }
    const std::size_t start = html.find('>', after), end = html.find(close, after);
    if (start == std::string::npos || end == std::string::npos || start > end) break;
    bodies.push_back(html.substr(start + 1, end - start - 1));
    p = end + close.size();
  }
  return bodies;
}

// Tables of a rendered page whose rows do not all have the same number of cells (<td>/<th>;
// the report uses no colspan): "table 3: rows with 3, 12 cells" for each such table.
inline std::vector<std::string> ragged_tables(const std::string& html) {
  std::vector<std::string> ragged;
  int index = 0;
  for (const auto& table : element_bodies(html, "table")) {
    ++index;
    std::set<long> widths;
    for (const auto& row : element_bodies(table, "tr"))
      widths.insert(static_cast<long>(element_bodies(row, "td").size() + element_bodies(row, "th").size()));
    if (widths.size() > 1) {
      std::string text = "table " + std::to_string(index) + ": rows with";
      for (long w : widths) text += " " + std::to_string(w);
      ragged.push_back(text + " cells");
    }
  }
  return ragged;
}

// The directories of the build that a page must not name: the source tree (which holds the
// build directory here) and the directory of the lrchain executable under test.
inline std::vector<std::string> build_paths_in(const std::string& html) {
  std::vector<std::string> found;
  std::vector<std::string> paths = {LRCHAIN_SOURCE_DIR};
#ifdef LRCHAIN_CLI
  paths.push_back(std::filesystem::path(LRCHAIN_CLI).parent_path().string());
#endif
  for (const auto& p : paths)
    if (!p.empty() && html.find(p) != std::string::npos) found.push_back(p);
  return found;
}

// LaTeX labels shown as text (outside the title attribute that keeps them as a tooltip).
inline std::vector<std::string> visible_latex_labels(const std::string& html) {
  std::vector<std::string> found;
  const std::regex label(R"((^|[^"\w])((?:eq|fig):[A-Za-z][\w:]*))");
  for (std::sregex_iterator it(html.begin(), html.end(), label), end; it != end; ++it) found.push_back((*it)[2]);
  return found;
}

}  // namespace lrchain::test

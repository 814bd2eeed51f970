#pragma once
// Checks of generated gnuplot scripts without drawing them: the text of a file, and the titles and
// labels whose enhanced text would turn an underscore into a subscript.
#include <filesystem>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace lrchain::test {

inline std::string file_text(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// The quoted strings after `title`, `label` and `xlabel`/`ylabel`/`cblabel` (single or double
// quotes) that hold an underscore not escaped by a backslash: enhanced text shows the next
// character as a subscript ("my_chain" as "my" and a subscript "c", then "hain").
inline std::vector<std::string> unescaped_underscores_in_text(const std::string& script) {
  std::vector<std::string> found;
  for (const std::string keyword : {"title ", "label "}) {
    for (std::size_t at = script.find(keyword); at != std::string::npos; at = script.find(keyword, at + 1)) {
      const std::size_t open = at + keyword.size();
      if (open >= script.size() || (script[open] != '\'' && script[open] != '"')) continue;
      const std::size_t close = script.find(script[open], open + 1);
      if (close == std::string::npos) continue;
      const std::string text = script.substr(open + 1, close - open - 1);
      for (std::size_t k = 0; k < text.size(); ++k)
        if (text[k] == '_' && (k == 0 || text[k - 1] != '\\')) {
          found.push_back(text);
          break;
        }
    }
  }
  return found;
}

// The screen rectangle {x, y, width, height} of every `plot`/`splot` of a multiplot script, from the
// `set origin` and `set size` in force (gnuplot's defaults 0,0 and 1,1).
struct PanelRectangle {
  double x = 0, y = 0, width = 1, height = 1;
};
inline std::vector<PanelRectangle> multiplot_panels(const std::string& script) {
  std::vector<PanelRectangle> panels;
  PanelRectangle now;
  std::istringstream in(script);
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("set origin ", 0) == 0)
      std::sscanf(line.c_str(), "set origin %lf,%lf", &now.x, &now.y);
    else if (line.rfind("set size ", 0) == 0 && line.find("ratio") == std::string::npos)
      std::sscanf(line.c_str(), "set size %lf,%lf", &now.width, &now.height);
    else if (line.rfind("plot ", 0) == 0 || line.rfind("splot ", 0) == 0)
      panels.push_back(now);
  }
  return panels;
}

// Whether two panels cover a common area (more than touching edges).
inline bool panels_overlap(const PanelRectangle& a, const PanelRectangle& b) {
  const double tolerance = 1e-9;
  return a.x + a.width > b.x + tolerance && b.x + b.width > a.x + tolerance && a.y + a.height > b.y + tolerance &&
         b.y + b.height > a.y + tolerance;
}

}  // namespace lrchain::test

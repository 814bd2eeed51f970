#pragma once
// Checks of generated gnuplot scripts without drawing them: the text of a file, and the titles and
// labels whose enhanced text would turn an underscore into a subscript.
#include <filesystem>
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

}  // namespace lrchain::test

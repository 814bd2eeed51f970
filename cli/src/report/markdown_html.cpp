// Markdown subset -> HTML for docs/paper-errata.md (see markdown_html.hpp).
#include "markdown_html.hpp"

#include <cctype>
#include <sstream>
#include <vector>

namespace lrchain::report {

std::string html_escape(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  for (char ch : text) switch (ch) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += ch;
    }
  return out;
}

std::string heading_anchor(const std::string& heading) {
  std::string id;
  for (unsigned char ch : heading) {
    if (std::isalnum(ch)) id += static_cast<char>(std::tolower(ch));
    else if (!id.empty() && id.back() != '-') id += '-';
  }
  while (!id.empty() && id.back() == '-') id.pop_back();
  return id;
}

namespace {

// `code` and **bold** inside one line of text.
std::string inline_html(const std::string& text) {
  std::string out;
  for (std::size_t i = 0; i < text.size();) {
    if (text[i] == '`') {
      const auto end = text.find('`', i + 1);
      if (end != std::string::npos) {
        out += "<code>" + html_escape(text.substr(i + 1, end - i - 1)) + "</code>";
        i = end + 1;
        continue;
      }
    }
    if (text.compare(i, 2, "**") == 0) {
      const auto end = text.find("**", i + 2);
      if (end != std::string::npos) {
        out += "<strong>" + html_escape(text.substr(i + 2, end - i - 2)) + "</strong>";
        i = end + 2;
        continue;
      }
    }
    out += html_escape(std::string(1, text[i]));
    ++i;
  }
  return out;
}

std::vector<std::string> table_cells(const std::string& line) {
  std::vector<std::string> cells;
  std::string s = line;
  if (!s.empty() && s.front() == '|') s.erase(0, 1);
  if (!s.empty() && s.back() == '|') s.pop_back();
  std::stringstream in(s);
  std::string cell;
  while (std::getline(in, cell, '|')) {
    const auto a = cell.find_first_not_of(' ');
    const auto b = cell.find_last_not_of(' ');
    cells.push_back(a == std::string::npos ? "" : cell.substr(a, b - a + 1));
  }
  return cells;
}

bool is_separator_row(const std::string& line) {
  return line.find_first_not_of("|-: ") == std::string::npos && line.find('-') != std::string::npos;
}

}  // namespace

std::string markdown_to_html(const std::string& markdown) {
  std::vector<std::string> lines;
  {
    std::stringstream in(markdown);
    std::string l;
    while (std::getline(in, l)) lines.push_back(l);
  }
  std::string html, paragraph;
  auto flush_paragraph = [&] {
    if (!paragraph.empty()) html += "<p>" + inline_html(paragraph) + "</p>\n";
    paragraph.clear();
  };
  for (std::size_t i = 0; i < lines.size(); ++i) {
    const std::string& line = lines[i];
    if (line.empty()) { flush_paragraph(); continue; }
    if (line[0] == '#') {
      flush_paragraph();
      std::size_t level = line.find_first_not_of('#');
      const std::string text = line.substr(line.find_first_not_of(' ', level));
      level = std::min<std::size_t>(level, 6);
      html += "<h" + std::to_string(level) + " id=\"" + heading_anchor(text) + "\">" +
              inline_html(text) + "</h" + std::to_string(level) + ">\n";
      continue;
    }
    if (line[0] == '|') {
      flush_paragraph();
      html += "<table>\n";
      bool header = i + 1 < lines.size() && is_separator_row(lines[i + 1]);
      for (; i < lines.size() && !lines[i].empty() && lines[i][0] == '|'; ++i) {
        if (is_separator_row(lines[i])) continue;
        const char* tag = header ? "th" : "td";
        html += "<tr>";
        for (const auto& c : table_cells(lines[i]))
          html += std::string("<") + tag + ">" + inline_html(c) + "</" + tag + ">";
        html += "</tr>\n";
        header = false;
      }
      --i;
      html += "</table>\n";
      continue;
    }
    if (line.rfind("- ", 0) == 0 || line.rfind("* ", 0) == 0) {
      flush_paragraph();
      html += "<ul>\n";
      while (i < lines.size() && (lines[i].rfind("- ", 0) == 0 || lines[i].rfind("* ", 0) == 0)) {
        std::string item = lines[i].substr(2);
        while (i + 1 < lines.size() && lines[i + 1].rfind("  ", 0) == 0) {
          ++i;
          item += " " + lines[i].substr(lines[i].find_first_not_of(' '));
        }
        html += "<li>" + inline_html(item) + "</li>\n";
        ++i;
      }
      --i;
      html += "</ul>\n";
      continue;
    }
    paragraph += (paragraph.empty() ? "" : " ") + line;
  }
  flush_paragraph();
  return html;
}

}  // namespace lrchain::report

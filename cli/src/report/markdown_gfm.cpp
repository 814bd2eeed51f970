// Markdown -> HTML through cmark-gfm (markdown_html.hpp).
#include <cmark-gfm-core-extensions.h>
#include <cmark-gfm.h>

#include <cctype>
#include <cstdlib>
#include <memory>
#include <mutex>
#include <regex>
#include <stdexcept>
#include <vector>

#include "markdown_html.hpp"
#include "rich_text.hpp"

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

// The plain text of a node (its text and code descendants).
std::string node_text(cmark_node* node) {
  std::string text;
  cmark_iter* it = cmark_iter_new(node);
  for (cmark_event_type ev; (ev = cmark_iter_next(it)) != CMARK_EVENT_DONE;) {
    cmark_node* n = cmark_iter_get_node(it);
    const auto type = cmark_node_get_type(n);
    if (ev == CMARK_EVENT_ENTER && (type == CMARK_NODE_TEXT || type == CMARK_NODE_CODE))
      if (const char* literal = cmark_node_get_literal(n)) text += literal;
  }
  cmark_iter_free(it);
  return text;
}

// Anchors of the document's headings, in document order.
std::vector<std::string> heading_anchors(cmark_node* document) {
  std::vector<std::string> anchors;
  for (cmark_node* n = cmark_node_first_child(document); n; n = cmark_node_next(n))
    if (cmark_node_get_type(n) == CMARK_NODE_HEADING) anchors.push_back(heading_anchor(node_text(n)));
  return anchors;
}

}  // namespace

std::string markdown_to_html(const std::string& markdown) {
  static std::once_flag registered;
  std::call_once(registered, [] { cmark_gfm_core_extensions_ensure_registered(); });
  const int options = CMARK_OPT_DEFAULT | CMARK_OPT_VALIDATE_UTF8;
  std::unique_ptr<cmark_parser, decltype(&cmark_parser_free)> parser(cmark_parser_new(options), cmark_parser_free);
  for (const char* name : {"table", "autolink", "strikethrough"}) {
    cmark_syntax_extension* extension = cmark_find_syntax_extension(name);
    if (!extension) throw std::runtime_error(std::string("cmark-gfm has no '") + name + "' extension");
    cmark_parser_attach_syntax_extension(parser.get(), extension);
  }
  cmark_parser_feed(parser.get(), markdown.data(), markdown.size());
  std::unique_ptr<cmark_node, decltype(&cmark_node_free)> document(cmark_parser_finish(parser.get()), cmark_node_free);
  std::unique_ptr<char, decltype(&std::free)> rendered(
      cmark_render_html(document.get(), options, cmark_parser_get_syntax_extensions(parser.get())), std::free);
  const std::string html = rendered ? rendered.get() : "";
  // cmark renders top-level headings as bare <hN>; give each its anchor, in order.
  const auto anchors = heading_anchors(document.get());
  std::string out;
  std::size_t next = 0, pos = 0;
  const std::regex heading_tag("<h([1-6])>");
  for (std::sregex_iterator it(html.begin(), html.end(), heading_tag), end; it != end; ++it) {
    out.append(html, pos, it->position() - pos);
    out += "<h" + (*it)[1].str() + (next < anchors.size() ? " id=\"" + anchors[next++] + "\"" : std::string()) + ">";
    pos = it->position() + it->length();
  }
  out.append(html, pos);
  return html_subscripts(out);
}

}  // namespace lrchain::report

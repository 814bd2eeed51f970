#pragma once
// A small Markdown-to-HTML converter for the project's own docs (docs/paper-errata.md) so the
// report can carry them as a static page: headings (with id anchors), paragraphs, "-" lists,
// pipe tables, `code` and **bold**. Not a general Markdown implementation.
#include <string>

namespace lrchain::report {

std::string html_escape(const std::string& text);
// The id a heading gets: lower case, runs of other characters replaced by '-'.
std::string heading_anchor(const std::string& heading);
// The HTML body of a Markdown document.
std::string markdown_to_html(const std::string& markdown);

}  // namespace lrchain::report

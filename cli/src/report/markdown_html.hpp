#pragma once
// Markdown to HTML for the project's docs carried by the report (docs/paper-errata.md), through
// cmark-gfm with GitHub's table extension; headings get GitHub-style id anchors.
#include <string>

namespace lrchain::report {

std::string html_escape(const std::string& text);
// The id a heading gets: lower case, runs of other characters replaced by '-'.
std::string heading_anchor(const std::string& heading);
// The HTML body of a GitHub-flavoured Markdown document (tables, autolinks, strikethrough).
std::string markdown_to_html(const std::string& markdown);

}  // namespace lrchain::report

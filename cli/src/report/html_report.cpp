// index.html and errata.html of `lrchain reproduce` (see html_report.hpp).
#include "html_report.hpp"

#include <fmt/format.h>

#include "lrchain/sim/output_files.hpp"
#include "markdown_html.hpp"

namespace lrchain::report {

namespace fs = std::filesystem;

namespace {

const char* style = R"(<style>
body{font-family:"DejaVu Sans",Arial,sans-serif;max-width:1200px;margin:1.5em auto;padding:0 1em;color:#222;line-height:1.4}
h1{margin-bottom:.2em}h2{border-bottom:1px solid #ccc;padding-bottom:.2em;margin-top:2em}
table{border-collapse:collapse;margin:.8em 0;font-size:.92em}
th,td{border:1px solid #ccc;padding:.25em .5em;vertical-align:top;text-align:left}
th{background:#f0f0f0}td.num{font-family:"DejaVu Sans Mono",monospace;white-space:nowrap}
.pass{background:#e3f5e1}.deviates{background:#fde2e1}.errata{background:#fff4cc}
.status{font-weight:bold;text-align:center}
figure{display:inline-block;margin:.6em;max-width:560px;vertical-align:top}
figure img{max-width:100%;border:1px solid #ddd}
figcaption{font-size:.88em;color:#333}
pre{background:#f6f6f6;padding:.5em;overflow-x:auto;font-size:.85em}
.failed{color:#a00;font-weight:bold}.muted{color:#666;font-size:.9em}
</style>
)";

std::string number(double v) {
  if (!std::isfinite(v)) return "&mdash;";
  return fmt::format("{:.7g}", v);
}

// The id of the first errata heading that starts with `prefix` ("" if there is none).
std::string errata_anchor(const std::string& markdown, const std::string& prefix) {
  std::size_t pos = 0;
  while ((pos = markdown.find('#', pos)) != std::string::npos) {
    if (pos == 0 || markdown[pos - 1] == '\n') {
      const auto start = markdown.find_first_not_of("# ", pos);
      const auto end = markdown.find('\n', pos);
      const std::string heading = markdown.substr(start, end - start);
      if (heading.rfind(prefix, 0) == 0) return heading_anchor(heading);
    }
    pos = markdown.find('\n', pos);
    if (pos == std::string::npos) break;
  }
  return "";
}

std::string row_html(const Comparison& r, const std::string& errata_markdown) {
  const Status s = r.status();
  std::string status = to_string(s);
  if (s == Status::errata) {
    const std::string id = errata_anchor(errata_markdown, r.errata_anchor);
    status = "<a href=\"errata.html" + (id.empty() ? "" : "#" + id) + "\">errata</a>";
  }
  std::string diff = "&mdash;";
  if (r.computed() && std::isfinite(r.paper)) diff = fmt::format("{:+.2g}", r.difference());
  std::string note = html_escape(r.note);
  if (!r.computed()) note = "not computed" + (note.empty() ? "" : ": " + note);
  return fmt::format(
      "<tr class=\"{}\"><td>{}</td><td>{}</td><td class=\"num\">{}</td><td class=\"num\">{}</td>"
      "<td class=\"num\">{}</td><td class=\"status\">{}</td><td>{}</td></tr>\n",
      to_string(s), html_escape(r.quantity), html_escape(r.where), html_escape(r.paper_text),
      number(r.ours), diff, status, note);
}

std::string section_html(const fs::path& dir, const Section& s, const std::string& errata_markdown) {
  std::string h = fmt::format("<h2 id=\"{}\">{}</h2>\n", s.id, html_escape(s.title));
  if (!s.intro.empty()) h += "<p>" + html_escape(s.intro) + "</p>\n";
  if (s.failed) h += "<p class=\"failed\">This step failed: " + html_escape(s.error) + "</p>\n";
  if (!s.rows.empty()) {
    h += "<table><tr><th>quantity</th><th>paper</th><th>paper value</th><th>ours</th>"
         "<th>ours &minus; paper</th><th>status</th><th>how / note</th></tr>\n";
    for (const auto& r : s.rows) h += row_html(r, errata_markdown);
    h += "</table>\n";
  }
  for (const auto& f : s.figures) {
    if (!fs::exists(dir / f.file)) {  // never link a missing image; say that it is missing
      h += fmt::format("<p class=\"failed\">{}: figure {} was not produced (its gnuplot script and data are "
                       "next to where it should be).</p>\n", html_escape(f.paper_figure), html_escape(f.file));
      continue;
    }
    h += fmt::format(
        "<figure><a href=\"{0}\"><img src=\"{0}\" alt=\"{1}\"></a><figcaption><b>{1}.</b> {2}"
        "</figcaption></figure>\n",
        html_escape(f.file), html_escape(f.paper_figure), html_escape(f.caption));
  }
  std::vector<std::string> links;
  for (const auto& l : s.links)
    if (fs::exists(dir / l)) links.push_back(fmt::format("<a href=\"{0}\">{0}</a>", html_escape(l)));
  if (!links.empty()) h += "<p class=\"muted\">Data: " + fmt::format("{}", fmt::join(links, ", ")) + "</p>\n";
  if (!s.commands.empty()) {
    h += "<pre>";
    for (const auto& c : s.commands) h += html_escape(c) + "\n";
    h += "</pre>\n";
  }
  h += fmt::format("<p class=\"muted\">Step time: {:.1f} s</p>\n", s.seconds);
  return h;
}

}  // namespace

void write_html_report(const fs::path& dir, const std::vector<Section>& sections,
                       const ReportInfo& info) {
  const Counts c = count(sections);
  std::string h = "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">\n"
                  "<title>lrchain: reproduction of the paper</title>\n";
  h += style;
  h += "</head><body>\n<h1>Breathers in a locally resonant granular chain: reproduction report</h1>\n";
  h += fmt::format(
      "<p>Produced by <code>lrchain reproduce --{}</code>, started {}, total run time {:.1f} s. "
      "Every number below was computed by this run; the paper's printed value is the target. "
      "<b>pass</b>: ours agrees within the paper's rounding (or the stated tolerance, or satisfies "
      "the stated bound); <b>errata</b>: ours disagrees and the disagreement is documented with "
      "evidence on the <a href=\"errata.html\">errata page</a>; <b>deviates</b>: ours disagrees "
      "and it is not (yet) explained.</p>\n",
      info.mode, html_escape(info.started), info.total_seconds);
  h += fmt::format(
      "<table><tr><th>rows</th><th class=\"pass\">pass</th><th class=\"deviates\">deviates</th>"
      "<th class=\"errata\">errata</th></tr><tr><td class=\"num\">{}</td><td class=\"num\">{}</td>"
      "<td class=\"num\">{}</td><td class=\"num\">{}</td></tr></table>\n",
      c.pass + c.deviates + c.errata, c.pass, c.deviates, c.errata);
  if (info.mode == "quick")
    h += "<p>This is the <b>quick</b> run: some lattices are smaller and some runs shorter than "
         "the paper's (each section says which); <code>lrchain reproduce --full</code> uses the "
         "paper's sizes and times.</p>\n";
  h += "<ul>\n";
  for (const auto& s : sections)
    h += fmt::format("<li><a href=\"#{}\">{}</a>{}</li>\n", s.id, html_escape(s.title),
                     s.failed ? " <span class=\"failed\">(failed)</span>" : "");
  h += "<li><a href=\"errata.html\">Paper errata</a></li>\n</ul>\n";
  for (const auto& s : sections) h += section_html(dir, s, info.errata_markdown);
  // Marks every figure data-load="ok" or "broken" once the browser has tried to load it (read by
  // the headless-browser test; harmless offline).
  h += "<script>document.querySelectorAll('img').forEach(function(img){function mark(){"
       "img.setAttribute('data-load',img.complete&&img.naturalWidth>0?'ok':'broken');}"
       "if(img.complete)mark();else{img.addEventListener('load',mark);img.addEventListener('error',mark);}});"
       "</script>\n";
  h += "</body></html>\n";

  std::string e = "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">\n"
                  "<title>lrchain: paper errata</title>\n";
  e += style;
  e += "</head><body>\n<p><a href=\"index.html\">&larr; back to the report</a></p>\n";
  if (info.errata_markdown.empty())
    e += "<p class=\"failed\">docs/paper-errata.md was not found (looked in " +
         html_escape(info.errata_source) + ").</p>\n";
  else
    e += "<p class=\"muted\">From " + html_escape(info.errata_source) + "</p>\n" +
         markdown_to_html(info.errata_markdown);
  e += "</body></html>\n";

  sim::write_file_atomic(dir, "errata.html", e);
  sim::write_file_atomic(dir, "index.html", h);
}

}  // namespace lrchain::report

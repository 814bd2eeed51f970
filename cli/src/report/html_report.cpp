// index.html and errata.html of `lrchain reproduce` (see html_report.hpp).
#include "html_report.hpp"

#include <fmt/format.h>

#include "lrchain/jobs/output_files.hpp"
#include "markdown_html.hpp"
#include "rich_text.hpp"

namespace lrchain::report {

namespace fs = std::filesystem;

namespace {

const char* style = R"(<style>
body{font-family:"DejaVu Sans",Arial,sans-serif;max-width:1250px;margin:1.5em auto;padding:0 1em;color:#222;line-height:1.4}
h1{margin-bottom:.2em}h2{border-bottom:1px solid #ccc;padding-bottom:.2em;margin-top:2em}
table{border-collapse:collapse;margin:.8em 0;font-size:.92em}
th,td{border:1px solid #ccc;padding:.25em .5em;vertical-align:top;text-align:left}
th{background:#f0f0f0}td.num{font-family:"DejaVu Sans Mono",monospace;white-space:nowrap}
td.tol{font-size:.88em;color:#333}
.pass{background:#e3f5e1}.deviates{background:#fde2e1}.erratum{background:#fff4cc}.unresolved{background:#e8e3f8}
.status{font-weight:bold;text-align:center}
.cite{border-bottom:1px dotted #888;cursor:help}
figure{display:inline-block;margin:.6em;max-width:560px;vertical-align:top}
figure img{max-width:100%;border:1px solid #ddd}
figcaption{font-size:.88em;color:#333}
pre{background:#f6f6f6;padding:.5em;overflow-x:auto;font-size:.85em}
.failed{color:#a00;font-weight:bold}.muted{color:#666;font-size:.9em}
table.provenance td:first-child{font-weight:bold;white-space:nowrap}
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

// HTML without its tags (for an alt attribute); entities stay.
std::string plain_text(const std::string& html) {
  std::string out;
  bool in_tag = false;
  for (char ch : html) {
    if (ch == '<') in_tag = true;
    else if (ch == '>') in_tag = false;
    else if (!in_tag) out += ch;
  }
  return out;
}

std::string row_id(const Section& s, std::size_t k) { return fmt::format("row-{}-{}", s.id, k + 1); }

std::string row_html(const Comparison& r, const std::string& id, const std::string& errata_markdown) {
  const Status s = r.status();
  std::string status = to_string(s);
  if (s == Status::erratum || s == Status::unresolved) {
    const std::string anchor = errata_anchor(errata_markdown, r.errata_anchor);
    status = "<a href=\"errata.html" + (anchor.empty() ? "" : "#" + anchor) + "\">" + status + "</a>";
  }
  // ours - paper only where the paper prints a value; a bound or a statement in words is not a
  // difference.
  std::string diff = "&mdash;";
  if (r.claim == Claim::equals && !r.qualitative && r.computed() && std::isfinite(r.paper))
    diff = fmt::format("{:+.2g}", r.difference());
  std::string note = rich_text(r.note);
  if (!r.computed()) note = "not computed" + (note.empty() ? "" : ": " + note);
  if (r.qualitative) note = "qualitative check" + (note.empty() ? "" : ": " + note);
  return fmt::format(
      "<tr id=\"{}\" class=\"{}\"><td>{}</td><td>{}</td><td{}>{}</td><td class=\"num\">{}</td>"
      "<td class=\"num\">{}</td><td class=\"tol\">{}</td><td class=\"status\">{}</td><td>{}</td></tr>\n",
      id, to_string(s), rich_text(r.quantity), rich_text(r.where), r.qualitative ? "" : " class=\"num\"",
      rich_text(r.paper_text), number(r.ours), diff,
      rich_text(r.tolerance_text()), status, note);
}

std::string section_html(const fs::path& dir, const Section& s, const std::string& errata_markdown) {
  std::string h = fmt::format("<h2 id=\"{}\">{}</h2>\n", s.id, rich_text(s.title));
  if (!s.intro.empty()) h += "<p>" + rich_text(s.intro) + "</p>\n";
  if (s.failed) h += "<p class=\"failed\">This step failed: " + html_escape(s.error) + "</p>\n";
  if (!s.rows.empty()) {
    h += "<table><tr><th>quantity</th><th>paper</th><th>paper value</th><th>ours</th>"
         "<th>ours &minus; paper</th><th>tolerance (source)</th><th>status</th><th>how / note</th></tr>\n";
    for (std::size_t k = 0; k < s.rows.size(); ++k) h += row_html(s.rows[k], row_id(s, k), errata_markdown);
    h += "</table>\n";
  }
  for (const auto& f : s.figures) {
    if (!fs::exists(dir / f.file)) {  // never link a missing image; say that it is missing
      h += fmt::format("<p class=\"failed\">{}: figure {} was not produced (its gnuplot script and data are "
                       "next to where it should be).</p>\n", rich_text(f.paper_figure), html_escape(f.file));
      continue;
    }
    // A browser shows PNG and SVG inline; a PDF figure (--figure-format pdf) is linked.
    const bool pdf = f.file.size() > 4 && f.file.compare(f.file.size() - 4, 4, ".pdf") == 0;
    h += fmt::format(
        fmt::runtime(pdf ? "<figure><a href=\"{0}\">{0} (PDF)</a><figcaption><b>{2}.</b> {3}</figcaption></figure>\n"
                         : "<figure><a href=\"{0}\"><img src=\"{0}\" alt=\"{1}\"></a><figcaption><b>{2}.</b> {3}"
                           "</figcaption></figure>\n"),
        html_escape(f.file), plain_text(rich_text(f.paper_figure)), rich_text(f.paper_figure), rich_text(f.caption));
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

// Which lrchain, machine and command produced the report. The program is shown by its name (the
// JSON summary has its full path), so the page names no directory of the build.
std::string provenance_html(const Provenance& p) {
  std::string command;
  for (const auto& a : p.command_line)
    command += command.empty() ? fs::path(a).filename().string() : " " + a;
  auto row = [](const std::string& k, const std::string& v) {
    return "<tr><td>" + k + "</td><td>" + (v.empty() ? std::string("unknown") : html_escape(v)) + "</td></tr>\n";
  };
  return "<table class=\"provenance\">\n" + row("lrchain", p.build.version) + row("git commit", p.build.commit) +
         row("compiler", p.build.compiler) + row("build type", p.build.build_type) +
         row("machine", p.cores > 0 ? fmt::format("{} cores", p.cores) : std::string()) + row("date (UTC)", p.date) +
         row("command", command) + "</table>\n";
}

// The totals, each count of disagreeing rows followed by links to those rows.
std::string totals_html(const std::vector<Section>& sections, const Counts& c) {
  std::string h = fmt::format(
      "<table><tr><th>rows</th><th class=\"pass\">pass</th><th class=\"deviates\">deviates</th>"
      "<th class=\"erratum\">erratum</th><th class=\"unresolved\">unresolved</th></tr><tr><td class=\"num\">{}</td>"
      "<td class=\"num\">{}</td><td class=\"num\">{}</td><td class=\"num\">{}</td><td class=\"num\">{}</td></tr></table>\n",
      c.rows(), c.pass, c.deviates, c.erratum, c.unresolved);
  for (const Status status : {Status::deviates, Status::unresolved, Status::erratum}) {
    std::vector<std::string> links;
    for (const auto& s : sections)
      for (std::size_t k = 0; k < s.rows.size(); ++k)
        if (s.rows[k].status() == status)
          links.push_back(fmt::format("<li><a href=\"#{}\">{}</a> ({})</li>", row_id(s, k), rich_text(s.rows[k].quantity),
                                      rich_text(s.rows[k].where)));
    if (links.empty()) continue;
    h += fmt::format("<p><b class=\"{0}\">{0}</b> ({1}):</p>\n<ul>\n{2}\n</ul>\n", to_string(status), links.size(),
                     fmt::join(links, "\n"));
  }
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
      "<p>Produced by <code>lrchain reproduce --{}</code> in {:.1f} s. Every number below was computed by this "
      "run; the paper's printed value is the target, and every row shows its tolerance and where the tolerance "
      "comes from. <b>pass</b>: ours agrees within the tolerance (or satisfies the stated bound); "
      "<b>erratum</b>: ours disagrees and an independent computation, given on the <a href=\"errata.html\">errata "
      "page</a>, shows the printed value is wrong; <b>unresolved</b>: ours disagrees, the errata page gives what "
      "is known, and the cause is not proven; <b>deviates</b>: ours disagrees and it is not explained. Rows where "
      "the paper states a quality in words are qualitative checks: the criterion is ours, and ours &minus; "
      "paper is not shown. Equations and figures are numbered as in the compiled paper (hover for the LaTeX "
      "label).</p>\n",
      info.mode, info.total_seconds);
  h += provenance_html(info.provenance);
  h += totals_html(sections, c);
  if (info.mode == "quick")
    h += "<p>This is the <b>quick</b> run: some lattices are smaller and some runs shorter than "
         "the paper's (each section says which); <code>lrchain reproduce --full</code> uses the "
         "paper's sizes and times.</p>\n";
  h += "<ul>\n";
  for (const auto& s : sections)
    h += fmt::format("<li><a href=\"#{}\">{}</a>{}</li>\n", s.id, rich_text(s.title),
                     s.failed ? " <span class=\"failed\">(failed)</span>" : "");
  h += "<li><a href=\"errata.html\">Paper errata and unresolved differences</a></li>\n</ul>\n";
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
    e += "<p class=\"failed\">The errata page (docs/paper-errata.md) was not found with this lrchain; give it "
         "with <code>lrchain reproduce --errata FILE</code>.</p>\n";
  else
    e += markdown_to_html(info.errata_markdown) +
         "<p class=\"muted\">docs/paper-errata.md of lrchain " + html_escape(info.provenance.build.version) + "</p>\n";
  e += "</body></html>\n";

  jobs::write_file_atomic(dir, "errata.html", e);
  jobs::write_file_atomic(dir, "index.html", h);
}

}  // namespace lrchain::report

#pragma once
// Writes the report directory's index.html (tables of paper-vs-ours numbers, figures with
// captions, commands, totals) and errata.html (docs/paper-errata.md as HTML). Static HTML that
// only links files that exist, so it reads offline with no broken link.
#include <filesystem>
#include <string>
#include <vector>

#include "lrchain/provenance.hpp"
#include "report.hpp"

namespace lrchain::report {

struct ReportInfo {
  std::string mode;            // "quick" or "full"
  double total_seconds = 0;
  std::string errata_markdown; // contents of docs/paper-errata.md ("" if not found)
  Provenance provenance;       // which lrchain, machine and command line produced the report
};

// Writes dir/index.html and dir/errata.html (atomically, each via a temporary name).
void write_html_report(const std::filesystem::path& dir, const std::vector<Section>& sections,
                       const ReportInfo& info);

}  // namespace lrchain::report

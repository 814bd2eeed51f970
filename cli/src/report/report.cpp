// Status of a paper-vs-ours comparison and the report's totals.
#include "report.hpp"

namespace lrchain::report {

const char* to_string(Status s) {
  switch (s) {
    case Status::pass: return "pass";
    case Status::deviates: return "deviates";
    case Status::errata: return "errata";
  }
  return "?";
}

bool Comparison::agrees() const {
  if (!computed()) return false;
  switch (claim) {
    case Claim::equals: return std::abs(ours - paper) <= tolerance;
    case Claim::below: return ours < paper;
    case Claim::above: return ours > paper;
  }
  return false;
}

// A disagreement explained on the errata page is "errata"; any other (or a number we could not
// compute) is "deviates".
Status Comparison::status() const {
  if (agrees()) return Status::pass;
  if (!computed()) return Status::deviates;
  return errata_anchor.empty() ? Status::deviates : Status::errata;
}

Counts count(const std::vector<Section>& sections) {
  Counts c;
  for (const auto& s : sections)
    for (const auto& r : s.rows) switch (r.status()) {
        case Status::pass: ++c.pass; break;
        case Status::deviates: ++c.deviates; break;
        case Status::errata: ++c.errata; break;
      }
  return c;
}

}  // namespace lrchain::report

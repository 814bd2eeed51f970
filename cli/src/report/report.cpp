// Status of a paper-vs-ours comparison, its tolerance as shown, and the report's totals.
#include "report.hpp"

#include <fmt/format.h>

namespace lrchain::report {

const char* to_string(Status s) {
  switch (s) {
    case Status::pass: return "pass";
    case Status::deviates: return "deviates";
    case Status::erratum: return "erratum";
    case Status::unresolved: return "unresolved";
  }
  return "?";
}

double rounding_of(const std::string& printed) {
  const auto start = printed.find_first_of("0123456789");
  if (start == std::string::npos) return 0;
  auto end = printed.find_first_not_of("0123456789.", start);
  if (end == std::string::npos) end = printed.size();
  const std::string digits = printed.substr(start, end - start);
  const auto dot = digits.find('.');
  const int decimals = dot == std::string::npos ? 0 : static_cast<int>(digits.size() - dot - 1);
  return 0.5 * std::pow(10.0, -decimals);
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

// A disagreement documented on the errata page is an erratum (proven) or unresolved; any other
// (or a number we could not compute) deviates.
Status Comparison::status() const {
  if (agrees()) return Status::pass;
  if (!computed() || errata_anchor.empty()) return Status::deviates;
  return disagreement == Disagreement::erratum ? Status::erratum : Status::unresolved;
}

std::string Comparison::tolerance_text() const {
  const std::string sign = claim == Claim::below ? "<" : claim == Claim::above ? ">" : "=";
  if (qualitative) return fmt::format("criterion: ours {} {:g}{}", sign, paper,
                                      tolerance_source.empty() ? "" : " (" + tolerance_source + ")");
  if (claim != Claim::equals)
    return "bound stated by the paper" + (tolerance_source.empty() ? "" : " (" + tolerance_source + ")");
  std::string source = tolerance_source;
  if (source.empty()) {
    const bool approximate = paper_text.find('~') != std::string::npos;
    const double half_unit = rounding_of(paper_text);
    if (half_unit > 0 && std::abs(tolerance - half_unit) <= 1e-9 * half_unit)
      source = approximate ? "rounding of the digits after \"~\"" : "rounding of the printed digits";
    else if (approximate && half_unit > 0)
      source = fmt::format("stated \"~\": {:g} unit(s) of the last printed digit", tolerance / (2 * half_unit));
    else if (tolerance == 0)
      source = "exact";
    else
      source = "set by the report";
  }
  return fmt::format("±{:.2g} ({})", tolerance, source);
}

Counts count(const std::vector<Section>& sections) {
  Counts c;
  for (const auto& s : sections)
    for (const auto& r : s.rows) switch (r.status()) {
        case Status::pass: ++c.pass; break;
        case Status::deviates: ++c.deviates; break;
        case Status::erratum: ++c.erratum; break;
        case Status::unresolved: ++c.unresolved; break;
      }
  return c;
}

}  // namespace lrchain::report

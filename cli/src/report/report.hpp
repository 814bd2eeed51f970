#pragma once
// The reproduction report of `lrchain reproduce`: per paper section, the numbers the paper quotes
// next to ours (pass / deviates / erratum / unresolved), each with its tolerance and where that
// tolerance comes from, and the figures with captions naming the paper figure they correspond to.
// Plain data; html_report.hpp writes it.
#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace lrchain::report {

inline constexpr double not_computed = std::numeric_limits<double>::quiet_NaN();

// pass: ours agrees within the tolerance (or satisfies the bound).
// deviates: ours disagrees and the disagreement is not documented (or ours was not computed).
// erratum: ours disagrees and an independent computation, documented on the errata page, proves
//   the printed value wrong.
// unresolved: ours disagrees, the errata page documents what is known, the cause is not proven.
enum class Status { pass, deviates, erratum, unresolved };
const char* to_string(Status s);

// How a documented disagreement is classified (see Status).
enum class Disagreement { erratum, unresolved };

// How the paper states a number: a value (with an absolute tolerance from its rounding or from
// "approximately"), or a bound (ours must be below / above it).
enum class Claim { equals, below, above };

struct Comparison {
  std::string quantity;       // what is compared, e.g. "omega_opt = omega_+(pi), rho = 1/3"
  std::string where;          // where the paper states it, e.g. "Sec. 5.3"
  std::string paper_text;     // as printed, e.g. "2.4495", "< 3.5 %", "~ 0.23"
  double paper = not_computed;
  double ours = not_computed;
  double tolerance = 0;       // absolute, for Claim::equals
  std::string tolerance_source;  // where the tolerance comes from ("" : inferred from paper_text)
  Claim claim = Claim::equals;
  // The paper states a quality in words ("optical breather", "set in motion"); `paper` is the
  // criterion we test it with, and ours - paper is not a difference from the paper.
  bool qualitative = false;
  std::string errata_anchor;  // start of the errata heading that explains a disagreement
  Disagreement disagreement = Disagreement::unresolved;
  std::string note;           // how ours was computed, or why it differs

  bool computed() const { return std::isfinite(ours); }
  double difference() const { return ours - paper; }
  bool agrees() const;
  Status status() const;
  // The tolerance as a reader sees it, with its source: "±5e-05 (rounding of 2.4495)".
  std::string tolerance_text() const;
};

struct Figure {
  std::string file;          // PNG, relative to the report directory
  std::string paper_figure;  // e.g. "Fig. 6 (fig:focus1)"
  std::string caption;
};

struct Section {
  std::string id;            // step id, also the sub-directory of its outputs
  std::string title;
  std::string intro;         // what was run (sizes, times) and how it differs from the paper's run
  std::vector<Comparison> rows;
  std::vector<Figure> figures;
  std::vector<std::string> commands;  // the lrchain commands that produced the outputs
  std::vector<std::string> links;     // other files worth opening (summary.json, CSV), relative
  double seconds = 0;
  bool failed = false;
  std::string error;          // why the step failed
};

struct Counts {
  int pass = 0, deviates = 0, erratum = 0, unresolved = 0;
  int rows() const { return pass + deviates + erratum + unresolved; }
};
Counts count(const std::vector<Section>& sections);

}  // namespace lrchain::report

namespace lrchain::report {

// A row for a value the paper prints: pass when |ours - paper| <= tolerance.
inline Comparison equals_row(std::string quantity, std::string where, std::string paper_text,
                             double paper, double ours, double tolerance, std::string note = {}) {
  Comparison c;
  c.quantity = std::move(quantity);
  c.where = std::move(where);
  c.paper_text = std::move(paper_text);
  c.paper = paper;
  c.ours = ours;
  c.tolerance = tolerance;
  c.note = std::move(note);
  return c;
}

// A row for a bound the paper states ("errors remain less than 3.5 %"): pass when ours < bound.
inline Comparison below_row(std::string quantity, std::string where, std::string paper_text,
                            double bound, double ours, std::string note = {}) {
  Comparison c = equals_row(std::move(quantity), std::move(where), std::move(paper_text), bound,
                            ours, 0, std::move(note));
  c.claim = Claim::below;
  return c;
}

// Marks a row whose disagreement is proven wrong in the paper by the errata page's heading
// starting with `anchor`.
inline Comparison erratum(Comparison c, std::string anchor) {
  c.errata_anchor = std::move(anchor);
  c.disagreement = Disagreement::erratum;
  return c;
}

// Marks a row whose disagreement the errata page (heading starting with `anchor`) documents
// without a proven cause.
inline Comparison unresolved(Comparison c, std::string anchor) {
  c.errata_anchor = std::move(anchor);
  c.disagreement = Disagreement::unresolved;
  return c;
}

// A row checking a statement the paper makes in words with the numeric criterion `claim` against
// `criterion` (e.g. y/x < 0 for "optical breather").
inline Comparison qualitative_row(std::string quantity, std::string where, std::string paper_text, Claim claim,
                                  double criterion, double ours, std::string note = {}) {
  Comparison c = equals_row(std::move(quantity), std::move(where), std::move(paper_text), criterion, ours, 0,
                            std::move(note));
  c.claim = claim;
  c.qualitative = true;
  return c;
}

// Sets where the tolerance of a row comes from.
inline Comparison with_tolerance_source(Comparison c, std::string source) {
  c.tolerance_source = std::move(source);
  return c;
}

// Half a unit in the last printed decimal of a number as printed ("1.892" -> 5e-4, "~ 0.23" -> 5e-3).
double rounding_of(const std::string& printed);

}  // namespace lrchain::report

#pragma once
// The reproduction report of `lrchain reproduce` (issue 6): per paper section, the numbers the
// paper quotes next to ours (pass / deviates / errata) and the figures with captions naming the
// paper figure they correspond to. Plain data; html_report.hpp writes it.
#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace lrchain::report {

inline constexpr double not_computed = std::numeric_limits<double>::quiet_NaN();

enum class Status { pass, deviates, errata };
const char* to_string(Status s);

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
  Claim claim = Claim::equals;
  std::string errata_anchor;  // start of the errata heading that explains a disagreement
  std::string note;           // how ours was computed, or why it differs

  bool computed() const { return std::isfinite(ours); }
  double difference() const { return ours - paper; }
  bool agrees() const;
  Status status() const;
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
  int pass = 0, deviates = 0, errata = 0;
};
Counts count(const std::vector<Section>& sections);

}  // namespace lrchain::report

namespace lrchain::report {

// A row for a value the paper prints: pass when |ours - paper| <= tolerance.
inline Comparison equals_row(std::string quantity, std::string where, std::string paper_text,
                             double paper, double ours, double tolerance, std::string note = {},
                             std::string errata = {}) {
  Comparison c;
  c.quantity = std::move(quantity);
  c.where = std::move(where);
  c.paper_text = std::move(paper_text);
  c.paper = paper;
  c.ours = ours;
  c.tolerance = tolerance;
  c.note = std::move(note);
  c.errata_anchor = std::move(errata);
  return c;
}

// A row for a bound the paper states ("errors remain less than 3.5 %"): pass when ours < bound.
inline Comparison below_row(std::string quantity, std::string where, std::string paper_text,
                            double bound, double ours, std::string note = {},
                            std::string errata = {}) {
  Comparison c = equals_row(std::move(quantity), std::move(where), std::move(paper_text), bound,
                            ours, 0, std::move(note), std::move(errata));
  c.claim = Claim::below;
  return c;
}

}  // namespace lrchain::report

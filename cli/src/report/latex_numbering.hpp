#pragma once
// The numbers the compiled paper gives its equations and figures ("eq. (12)", "Fig. 7"), so the
// report cites them as a reader of the paper sees them and keeps the LaTeX label as a tooltip.
// paper_numbers() is the table for the paper; number_labels() derives such a table from LaTeX
// source (a test checks the two agree when the paper's source is at hand).
#include <map>
#include <optional>
#include <string>

namespace lrchain::report {

struct PaperNumber {
  enum class Kind { equation, figure } kind = Kind::equation;
  int number = 0;
};

// Label -> number, by counting what LaTeX counts: equation environments, the numbered rows of
// eqnarray/align/gather (a row without \nonumber or \notag; a \label refers to the counter as it
// stands in its row), one number per figure environment. Comments are removed and argument-free
// \def macros that open or close environments (\def\beq{\begin{equation}}) are expanded first.
// Not handled (absent from the paper): subequations, \tag, \numberwithin, per-section numbering.
std::map<std::string, PaperNumber> number_labels(const std::string& latex);

// The table for breathers-locally-resonant-granular-chain.tex (generated with number_labels()).
const std::map<std::string, PaperNumber>& paper_numbers();

// The number of `label` ("eq:disp1d" also finds "disp1d", "fig:midarkb" finds "midarkb").
std::optional<PaperNumber> paper_number(const std::string& label);

}  // namespace lrchain::report

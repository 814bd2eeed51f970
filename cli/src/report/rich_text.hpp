#pragma once
// The report's prose and table cells as a physicist reads them: ASCII physics names rendered
// (omega'' -> ω″, h_tilde -> h̃, rho -> ρ, c_+ -> c₊ as a subscript, ||x||_inf -> ‖x‖∞) and LaTeX
// labels replaced by the numbers of the compiled paper ("fig:focus3" -> "Fig. 7", "eq:disp1d" ->
// "eq. (7)"), the label kept as a tooltip. Everything else is HTML-escaped.
#include <string>

namespace lrchain::report {

std::string rich_text(const std::string& text);

// Rendered HTML (the errata page) with the ASCII subscripts of its text shown as subscripts:
// x_n, E_x, T_b, ω_b, ω_opt -> x<sub>n</sub>, ...; a base of one or two ASCII letters or one Greek
// letter, a subscript of up to four letters or digits. Tags, <code> and <pre> are left as they are,
// and so are longer names (max_E_x).
std::string html_subscripts(const std::string& html);

// Plain text (help, tables) with the LaTeX labels replaced by the compiled paper's numbers
// ("eq:disp1d" -> "eq. (7)", "fig:focus3" -> "Fig. 7"); unknown labels and everything else unchanged.
std::string plain_citations(const std::string& text);

}  // namespace lrchain::report

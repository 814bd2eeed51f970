#pragma once
// Text in the CLI's gnuplot figures. The figures use gnuplot's enhanced text mode (x_{n}, ω_{b},
// T_{b} as subscripts, as in the simulator's figures); a name from a model file or the user
// ("diatomic_chain") is shown as written.
#include <string>

#include "lrchain/jobs/gnuplot_text.hpp"

namespace lrchain::cli {

// `text` for a single-quoted gnuplot string in enhanced mode, shown literally (the project's one
// escaping function, lrchain/jobs/gnuplot_text.hpp).
inline std::string gnuplot_literal(const std::string& text) {
  return jobs::gnuplot_text(text, jobs::GnuplotTextMode::enhanced);
}

}  // namespace lrchain::cli

#pragma once
// Forwarding header: user text in gnuplot scripts is the job layer's (lrchain/jobs/gnuplot_text.hpp).
// Kept while cli/src/figure_text.hpp and regime_command.cpp include this path (they link
// lrchain_jobs); include the jobs header there and delete this file. Not installed.
#include "lrchain/jobs/gnuplot_text.hpp"

namespace lrchain::sim {
using jobs::gnuplot_file_name;
using jobs::gnuplot_string;
using jobs::gnuplot_text;
using jobs::GnuplotTextMode;
}  // namespace lrchain::sim

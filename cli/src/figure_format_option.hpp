#pragma once
// --figure-format png|svg|pdf: the file format of the gnuplot figures a subcommand draws (cairo
// terminals pngcairo, svg, pdfcairo).
#include <CLI/CLI.hpp>
#include <string>

#include "lrchain/jobs/figure_format.hpp"

namespace lrchain::cli {

// Adds --figure-format to `app`; the value sets the process-wide format (lrchain::jobs::set_figure_format).
inline CLI::Option* add_figure_format(CLI::App& app) {
  auto* opt = app.add_option_function<std::string>(
      "--figure-format",
      [](const std::string& text) { jobs::set_figure_format(jobs::parse_figure_format(text)); },
      "file format of the figures: png (default), svg or pdf (gnuplot's cairo terminals)");
  opt->type_name("png|svg|pdf");
  return opt;
}

}  // namespace lrchain::cli

#pragma once
// The file format figures are drawn in (--figure-format): gnuplot's cairo terminals pngcairo, svg
// and pdfcairo. Scripts are written for pngcairo; Figures (output_files.hpp) converts them to the
// format chosen here.
#include <algorithm>
#include <string>

#include <fmt/format.h>

namespace lrchain::jobs {

enum class FigureFormat { png, svg, pdf };
// "png", "svg" or "pdf"; anything else throws lrchain::InvalidParameter naming figure-format.
FigureFormat parse_figure_format(const std::string& text);
// The format of every figure drawn after the call, process-wide (default png).
void set_figure_format(FigureFormat format);
FigureFormat figure_format();
// The option's name as given to it: "png", "svg" or "pdf".
std::string figure_format_name();
// `png_name` (a name ending in .png, as the scripts are written) with the current format's extension.
std::string figure_file_name(const std::string& png_name);
// A pngcairo script rewritten for the current format: `set terminal pngcairo size W,H ...` becomes
// the svg or pdfcairo terminal of the same proportions (W/72 x H/72 inches for pdf, so fonts keep
// their size relative to the figure), and the default output name gets the format's extension.
std::string script_for_format(const std::string& script_text);

// `every a:b ` for a space-time image of `sites` x `rows` drawn about `pixels` wide and high: gnuplot
// then reads every a-th site of every b-th row. It draws the same picture at a fraction of the cost
// (an image of N = 2000 sites over 1400 rows took 13 s of CPU time in full, 2.4 s with every 3:2).
inline std::string image_every(std::size_t sites, std::size_t rows, std::size_t pixels = 700) {
  return fmt::format("every {}:{} ", std::max<std::size_t>(1, sites / pixels), std::max<std::size_t>(1, rows / pixels));
}
// The same for a recorded field (its sites and its number of rows).
template <class Field>
std::string image_every(const Field& field) {
  return image_every(field.sites, field.times.size());
}

// gnuplot palette for colour maps: viridis (perceptually uniform, readable in grey), sampled at
// ten points of matplotlib's table.
inline constexpr const char* viridis_palette =
    "set palette defined (0 '#440154', 1 '#482878', 2 '#3e4989', 3 '#31688e', 4 '#26828e', 5 '#1f9e89', "
    "6 '#35b779', 7 '#6ece58', 8 '#b5de2b', 9 '#fde725')";

}  // namespace lrchain::jobs

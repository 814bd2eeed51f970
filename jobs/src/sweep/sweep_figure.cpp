// log10(scalar) over a two-axis grid, focusing boundaries and the fitted detuning exponent
// (sweep/sweep_figure.hpp).
#include "lrchain/jobs/sweep/sweep_figure.hpp"

#include <algorithm>
#include <array>
#include <functional>
#include <cmath>
#include <limits>
#include <sstream>

#include <fmt/format.h>

#include "lrchain/errors.hpp"
#include "lrchain/regime/focusing_intervals.hpp"
#include "lrchain/regime/model_regime.hpp"
#include "lrchain/jobs/model_experiment_config.hpp"
#include "lrchain/jobs/experiment_config.hpp"
#include "lrchain/jobs/gnuplot_text.hpp"
#include "lrchain/sim/least_squares.hpp"
#include "lrchain/jobs/output_files.hpp"
#include "lrchain/jobs/sweep/side_files.hpp"

namespace lrchain::jobs::sweep {

using namespace lrchain::sim;  // the numerics this job layer runs

namespace {

// The theta values where a focusing interval of the base config's chain begins or ends.
std::vector<double> focusing_boundaries(const Job& job) {
  std::vector<regime::FocusingInterval> intervals;
  if (const ModelSource* source = job.model_source()) {
    // A model file's base: its branch at the base's [parameters].
    const ModelExperimentConfig mc = load_model_experiment_config(job.base());
    const Model model = source->model(mc.parameters);
    intervals = regime::focusing_intervals(model, model.branch(mc.branch));
  } else {
    const BrightRunConfig b = load_experiment_config(job.base()).bright;
    intervals = regime::focusing_intervals(b.params, b.branch);
  }
  std::vector<double> ends;
  for (const auto& i : intervals) {
    if (i.lo > 0) ends.push_back(i.lo);
    ends.push_back(i.hi);
  }
  return ends;
}

// Exponent p of value ~ |y|^p for each x (NaN where fewer than two positive values).
std::vector<double> fitted_exponents(const Axis& x, const Axis& y, const SweepResults& r, std::size_t s) {
  std::vector<double> p;
  for (std::size_t i = 0; i < x.values.size(); ++i) {
    std::vector<double> ly, lv;
    for (std::size_t j = 0; j < y.values.size(); ++j) {
      const double v = r.scalars[s * r.points + i * y.values.size() + j];
      if (v > 0 && std::isfinite(v) && y.values[j] != 0) {
        ly.push_back(std::log(std::abs(y.values[j])));
        lv.push_back(std::log(v));
      }
    }
    p.push_back(ly.size() >= 2 ? least_squares_slope(ly, lv) : std::nan(""));
  }
  return p;
}

// Draws `figures` into dir; the files written, scripts and PNGs, appended to `files`.
void draw_figures(const std::filesystem::path& dir, const std::vector<FigureScript>& figures, std::vector<std::string>& files) {
  Figures drawn(dir);
  drawn.draw_all(figures);
  for (const auto& f : figures) files.push_back(f.script);
  for (const auto& png : drawn.drawn()) files.push_back(png);
  if (!drawn.warning().empty()) fmt::print(stderr, "{}\n", drawn.warning());
}

// The second axis is drawn on a log scale: one sign throughout and at least a decade.
bool second_axis_log(const Axis& y) {
  const bool y_negative = std::all_of(y.values.begin(), y.values.end(), [](double v) { return v < 0; });
  return std::all_of(y.values.begin(), y.values.end(), [&](double v) { return y_negative ? v < 0 : v > 0; }) &&
         std::abs(y.values.back() / y.values.front()) >= 10;
}

// A bright sweep over theta and a log range of detunings also gets the fitted exponent's figure.
bool draws_detuning_exponent(const SweepConfig& c) {
  return c.job == "bright" && c.axes.size() == 2 && c.axes[0].parameter == "bright.theta" &&
         c.axes[1].parameter == "bright.detuning" && second_axis_log(c.axes[1]);
}

// The cell of each axis value on the drawn axis: from half way to the next lower value to half way
// to the next higher one (on a log axis half way in the logarithm); an end value's cell is as wide
// on its open side as on the other, a single value's a unit (a decade) wide.
std::vector<std::pair<double, double>> cell_edges(const std::vector<double>& drawn, bool log_axis) {
  std::vector<double> at(drawn);
  if (log_axis)
    for (double& v : at) v = std::log10(v);
  std::vector<std::pair<double, double>> cells;
  for (const double v : at) {
    double below = -INFINITY, above = INFINITY;
    for (const double w : at) {
      if (w < v) below = std::max(below, w);
      if (w > v) above = std::min(above, w);
    }
    const double half_below = std::isfinite(below) ? (v - below) / 2 : std::isfinite(above) ? (above - v) / 2 : 0.5;
    const double half_above = std::isfinite(above) ? (above - v) / 2 : half_below;
    cells.emplace_back(v - half_below, v + half_above);
  }
  if (log_axis)
    for (auto& [lo, hi] : cells) lo = std::pow(10.0, lo), hi = std::pow(10.0, hi);
  return cells;
}

// The border between the cells where a flag holds and those where it does not, as segments {x0, y0,
// x1, y1} on the cells' shared edges; `flag(i, j)` is NaN where the point has no value (no border there).
using Segment = std::array<double, 4>;
std::vector<Segment> flag_border(const std::vector<std::pair<double, double>>& x_cells,
                                 const std::vector<std::pair<double, double>>& y_cells,
                                 const std::function<double(std::size_t, std::size_t)>& flag) {
  const auto order = [](const std::vector<std::pair<double, double>>& cells) {
    std::vector<std::size_t> k(cells.size());
    for (std::size_t i = 0; i < k.size(); ++i) k[i] = i;
    std::sort(k.begin(), k.end(), [&](std::size_t a, std::size_t b) { return cells[a].first < cells[b].first; });
    return k;
  };
  const auto differ = [](double a, double b) { return std::isfinite(a) && std::isfinite(b) && (a > 0.5) != (b > 0.5); };
  const std::vector<std::size_t> xs = order(x_cells), ys = order(y_cells);
  std::vector<Segment> border;
  for (std::size_t j = 0; j < y_cells.size(); ++j)
    for (std::size_t k = 0; k + 1 < xs.size(); ++k)
      if (differ(flag(xs[k], j), flag(xs[k + 1], j)))
        border.push_back({x_cells[xs[k]].second, y_cells[j].first, x_cells[xs[k]].second, y_cells[j].second});
  for (std::size_t i = 0; i < x_cells.size(); ++i)
    for (std::size_t k = 0; k + 1 < ys.size(); ++k)
      if (differ(flag(i, ys[k]), flag(i, ys[k + 1])))
        border.push_back({x_cells[i].first, y_cells[ys[k]].second, x_cells[i].second, y_cells[ys[k]].second});
  return border;
}

// A gnuplot array of `values` in order: "array name[n] = [v1, v2, ...]".
std::string gnuplot_array(const std::string& name, const std::vector<double>& values) {
  std::string a = fmt::format("array {}[{}] = [", name, values.size());
  for (std::size_t k = 0; k < values.size(); ++k) a += fmt::format("{}{:.17g}", k ? ", " : "", values[k]);
  return a + "]\n";
}

std::size_t index_of(const std::vector<std::string>& names, const std::string& name) {
  const auto it = std::find(names.begin(), names.end(), name);
  if (it == names.end()) throw std::logic_error("no column " + name);
  return std::size_t(it - names.begin());
}

}  // namespace

std::vector<std::string> sweep_figure_files(const SweepConfig& c) {
  if (c.figure.empty()) return {};
  if (draws_stability_figure(c)) {
    const std::string stem = c.output.stem().string() + "_stability";
    return {stem + ".dat", stem + "_marks.dat", stem + ".gp", stem + ".png"};
  }
  const std::string stem = c.output.stem().string() + "_" + c.figure;
  std::vector<std::string> files{stem + ".dat", stem + ".gp", stem + ".png"};
  if (draws_detuning_exponent(c))
    files.insert(files.end(), {stem + "_exponent.csv", stem + "_exponent.gp", stem + "_exponent.png"});
  return files;
}

std::vector<std::string> write_sweep_figures(const SweepConfig& c, const Job& job, const SweepResults& r,
                                             const std::string& scalar) {
  if (!c.grid || c.axes.size() != 2)
    throw InvalidParameter("figure", "needs a grid sweep of exactly two axes");
  const auto it = std::find(r.scalar_names.begin(), r.scalar_names.end(), scalar);
  if (it == r.scalar_names.end()) throw InvalidParameter("figure", "'" + scalar + "' is not a scalar of the job");
  const std::size_t s = std::size_t(it - r.scalar_names.begin());
  const Axis &x = c.axes[0], &y = c.axes[1];
  // A negative axis (the detuning on a branch with h_tilde < 0) is drawn by its magnitude.
  const bool y_negative = std::all_of(y.values.begin(), y.values.end(), [](double v) { return v < 0; });
  const bool y_log = second_axis_log(y);
  const double sign = y_negative ? -1.0 : 1.0;  // of the values drawn
  const std::string stem = c.output.stem().string() + "_" + scalar;
  const std::filesystem::path dir = output_directory(c);
  // A "wave fate" sweep's fate is a category (0 stable .. 4 disordered), drawn in its own colour, with
  // the points the NLS calls focusing (+), those whose exact wave has growth (x) and those that passed
  // through a dark stage (o, dark_from has a value) or a bright stage (triangle, bright_from) marked.
  const bool categorical = c.job == "wave fate" && scalar == "fate";
  const auto column = [&](const std::string& name) {
    const auto at = std::find(r.scalar_names.begin(), r.scalar_names.end(), name);
    return at == r.scalar_names.end() ? std::size_t(0) : std::size_t(at - r.scalar_names.begin());
  };
  const std::size_t focusing = column("focusing"), stable = column("stable"), dark_from = column("dark_from"),
                    bright_from = column("bright_from");

  std::ostringstream data;
  data << "# " << x.parameter << ' ' << (y_negative ? "-" : "") << y.parameter
       << (categorical ? " fate focusing stable dark_stage bright_stage" : " log10(" + scalar + ")") << "\n";
  for (std::size_t i = 0; i < x.values.size(); ++i) {
    for (std::size_t j = 0; j < y.values.size(); ++j) {
      const std::size_t point = i * y.values.size() + j;
      const double v = r.scalars[s * r.points + point];
      if (categorical)
        data << fmt::format("{} {} {} {} {} {} {}\n", x.values[i], y_negative ? -y.values[j] : y.values[j],
                            std::isfinite(v) ? fmt::format("{}", v) : "NaN", r.scalars[focusing * r.points + point],
                            r.scalars[stable * r.points + point],
                            std::isfinite(r.scalars[dark_from * r.points + point]) ? 1 : 0,
                            std::isfinite(r.scalars[bright_from * r.points + point]) ? 1 : 0);
      else
        data << fmt::format("{} {} {}\n", x.values[i], y_negative ? -y.values[j] : y.values[j],
                            v > 0 && std::isfinite(v) ? fmt::format("{}", std::log10(v)) : std::string("NaN"));
    }
    data << '\n';
  }
  write_file_atomic(dir, stem + ".dat", data.str());
  std::vector<std::string> files{stem + ".dat"};

  // Every text that comes from the sweep file (its name, the output's name, the axes) goes into the
  // script as a gnuplot string (gnuplot_text.hpp), never as script text.
  const std::string x_name = gnuplot_text(x.parameter), y_name = gnuplot_text(y.parameter), value = gnuplot_text(scalar);
  // Each point is drawn as its own cell (a box from cell_edges around it, in its own colour; a
  // point without a value is left blank), not as the corner of pm3d's interpolated quadrangles.
  // In the data file the block (column -1) is the x index and the line number ($0) counts x-major.
  std::vector<double> drawn_y;
  for (double v : y.values) drawn_y.push_back(sign * v);
  const auto x_cells = cell_edges(x.values, false), y_cells = cell_edges(drawn_y, y_log);
  std::vector<double> xlo, xhi, ylo, yhi;
  for (const auto& [lo, hi] : x_cells) xlo.push_back(lo), xhi.push_back(hi);
  for (const auto& [lo, hi] : y_cells) ylo.push_back(lo), yhi.push_back(hi);
  std::vector<double> ends;  // the focusing interval ends inside the drawn theta range
  if (c.job == "bright" && x.parameter == "bright.theta")
    for (double b : focusing_boundaries(job))
      if (b >= *std::min_element(xlo.begin(), xlo.end()) && b <= *std::max_element(xhi.begin(), xhi.end()))
        ends.push_back(b);
  std::ostringstream gp;
  gp << "# log10(" << value << ") over (" << x_name << ", " << y_name << ") from " << gnuplot_string(c.output.filename().string())
     << ". Re-run: gnuplot " << gnuplot_file_name(stem + ".gp") << "\n"
     << "if (!exists(\"outfile\")) outfile = " << gnuplot_file_name(stem + ".png") << "\n"
     << "set terminal pngcairo size 900,640 noenhanced\nset output outfile\n"
     << "set xlabel '" << x_name << "'\nset ylabel '" << (y_negative ? "|" + y_name + "|" : y_name) << "'\n"
     << (categorical ? "set rmargin 16\nset cbrange [-0.5:4.5]\nset cbtics ('stable' 0, 'intact' 1, 'modulated' 2, 'localized' 3, "
                       "'disordered' 4)\nset palette maxcolors 5 defined (0 '#1a9850', 1 '#a6d96a', 2 '#fee08b', 3 "
                       "'#f46d43', 4 '#762a83')\n"
                     : "set cblabel 'log10(" + value + ")'\nset palette rgbformulae 33,13,10\n")
     << (y_log ? "set logscale y\nset format y '1e%L'\n" : "")
     << "# the cell of each point on both axes\n"
     << gnuplot_array("xlo", xlo) << gnuplot_array("xhi", xhi) << gnuplot_array("ylo", ylo) << gnuplot_array("yhi", yhi)
     << "ny = " << y.values.size() << "\n"
     << fmt::format("set xrange [{}:{}]\nset yrange [{}:{}]\n", *std::min_element(xlo.begin(), xlo.end()),
                    *std::max_element(xhi.begin(), xhi.end()), *std::min_element(ylo.begin(), ylo.end()),
                    *std::max_element(yhi.begin(), yhi.end()))
     << "set title '" << gnuplot_text(c.name) << (categorical ? ": fate" : ": log10(" + value + ")")
     << (ends.empty() ? "" : "; dashed: focusing interval ends") << (categorical ? "'" : "; blank: no value'") << "\n"
     << (categorical ? "set bmargin 5\nset label 1 '+ NLS focusing (border dashed), x exact growth (border blue), o dark "
                       "stage, triangle bright stage; blank: no value' at screen 0.02, screen 0.025 font ',9'\n"
                     : "");
  for (double b : ends)
    gp << fmt::format("set arrow from {0}, graph 0 to {0}, graph 1 nohead dashtype 2 linewidth 2 front\n", b);
  if (categorical) {  // the exact wave's growth border (solid), then the NLS's focusing border (dashed, on top)
    const auto at = [&](std::size_t flag_column, bool negate) {
      return [&, flag_column, negate](std::size_t i, std::size_t j) {
        const double v = r.scalars[flag_column * r.points + i * y.values.size() + j];
        return (std::isfinite(v) && negate) ? 1 - v : v;
      };
    };
    gp << "# borders: NLS focusing (dashed black), exact growth (solid blue), on the cells' shared edges\n";
    for (const Segment& g : flag_border(x_cells, y_cells, at(stable, true)))
      gp << fmt::format("set arrow from {:.17g}, {:.17g} to {:.17g}, {:.17g} nohead linewidth 3 lc rgb '#2166ac' front\n",
                        g[0], g[1], g[2], g[3]);
    for (const Segment& g : flag_border(x_cells, y_cells, at(focusing, false)))
      gp << fmt::format("set arrow from {:.17g}, {:.17g} to {:.17g}, {:.17g} nohead dashtype 2 linewidth 3 lc rgb 'black' front\n",
                        g[0], g[1], g[2], g[3]);
  }
  gp << "plot " << gnuplot_file_name(stem + ".dat")
     << " using 1:2:(xlo[column(-1)+1]):(xhi[column(-1)+1]):(ylo[int(column(0))%ny+1]):(yhi[int(column(0))%ny+1]):3 "
        "with boxxyerror fillstyle solid 1.0 noborder fillcolor palette notitle"
     << (categorical ? ", '' using 1:($4 > 0 ? $2 : NaN) with points pointtype 1 pointsize 1.5 lc rgb 'black' notitle, "
                       "'' using 1:($5 < 1 ? $2 : NaN) with points pointtype 2 pointsize 1.5 lc rgb 'black' notitle, "
                       "'' using 1:($6 > 0 ? $2 : NaN) with points pointtype 6 pointsize 3 lw 2 lc rgb 'black' notitle, "
                       "'' using 1:($7 > 0 ? $2 : NaN) with points pointtype 8 pointsize 2.2 lw 2 lc rgb 'black' notitle"
                     : "")
     << "\n";
  std::vector<FigureScript> figures{{stem + ".gp", gp.str(), stem + ".png"}};

  if (draws_detuning_exponent(c)) {
    const auto p = fitted_exponents(x, y, r, s);
    std::ostringstream csv;
    csv << x.parameter << ",exponent\n";
    for (std::size_t i = 0; i < p.size(); ++i) csv << fmt::format("{},{}\n", x.values[i], p[i]);
    write_file_atomic(dir, stem + "_exponent.csv", csv.str());
    files.push_back(stem + "_exponent.csv");
    std::ostringstream g2;
    g2 << "# Exponent p of " << value << " ~ |detuning|^p fitted per theta. Re-run: gnuplot "
       << gnuplot_file_name(stem + "_exponent.gp") << "\n"
       << "if (!exists(\"outfile\")) outfile = " << gnuplot_file_name(stem + "_exponent.png") << "\n"
       << "set terminal pngcairo size 800,500 noenhanced\nset output outfile\nset datafile separator ','\n"
       << "set xlabel '" << x_name << "'\nset ylabel 'p in " << value << " ~ |detuning|^p'\nset grid\n"
       << "plot " << gnuplot_file_name(stem + "_exponent.csv") << " using 1:2 every ::1 with linespoints pointtype 7 notitle\n";
    figures.push_back({stem + "_exponent.gp", g2.str(), stem + "_exponent.png"});
  }
  draw_figures(dir, figures, files);
  return files;
}

namespace {

// Tics at the swept values when there are at most 20 (on a log axis gnuplot labels only the
// decades, which left the values of the columns unnamed); else gnuplot's own.
std::string axis_value_tics(const std::vector<double>& values) {
  if (values.size() > 20) return "";
  std::string tics = "set format x '%.3g'\nset xtics (";
  for (std::size_t k = 0; k < values.size(); ++k) tics += fmt::format("{}{:.17g}", k ? ", " : "", values[k]);
  return tics + ")\n";
}

}  // namespace

std::vector<std::string> write_stability_figure(const SweepConfig& c, const SweepResults& r) {
  if (c.axes.size() != 1 || r.row_names.empty())
    throw InvalidParameter("figure", "needs a one-axis \"dark continue\" or \"bright continue\" sweep");
  // A bright branch may be continued in a model parameter at fixed omega_b: drawn over that parameter.
  const bool bright = c.job == "bright continue";
  const std::string y_column = bright ? "parameter" : "omega_b";
  const Axis& x = c.axes[0];
  const bool x_log = std::all_of(x.values.begin(), x.values.end(), [](double v) { return v > 0; }) &&
                     *std::max_element(x.values.begin(), x.values.end()) >= 10 * *std::min_element(x.values.begin(), x.values.end());
  // Half the distance to the nearest other axis value (on the log scale when drawn so), for
  // drawing the two parts of a branch side by side.
  std::vector<double> drawn_x(x.values.size());
  for (std::size_t i = 0; i < x.values.size(); ++i) drawn_x[i] = x_log ? std::log(x.values[i]) : x.values[i];
  double gap = 0;
  for (std::size_t i = 0; i < drawn_x.size(); ++i)
    for (std::size_t j = 0; j < drawn_x.size(); ++j)
      if (drawn_x[i] != drawn_x[j]) gap = gap == 0 ? std::abs(drawn_x[i] - drawn_x[j]) : std::min(gap, std::abs(drawn_x[i] - drawn_x[j]));
  const double shift = gap > 0 ? 0.15 * gap : (x_log ? 0.02 : 0.02 * std::max(1.0, std::abs(x.values[0])));
  auto shifted = [&](double v, double side) { return x_log ? v * std::exp(side * shift) : v + side * shift; };

  const std::size_t columns = r.row_names.size(), omega = index_of(r.row_names, y_column),
                    stability = index_of(r.row_names, "stability"), part = index_of(r.row_names, "part");
  const std::size_t turning = index_of(r.scalar_names, "first_turning_point"), edge = index_of(r.scalar_names, "omega_edge");
  const std::string stem = c.output.stem().string() + "_stability";
  const std::filesystem::path dir = output_directory(c);
  std::ostringstream points, marks;
  points << "# drawn " << x.parameter << ", " << y_column
         << ", class (0 stable, 1 real-unstable, 2 oscillatory-unstable, 3 no Floquet), part, " << x.parameter << "\n";
  marks << "# " << x.parameter << ", first turning point " << y_column << ", band edge omega\n";
  for (std::size_t p = 0; p < r.points; ++p) {
    const double v = x.values[p];
    for (std::size_t i = 0; i + columns <= r.rows[p].size(); i += columns) {
      const double stability_code = r.rows[p][i + stability];  // NaN: a bright branch without Floquet
      const int code = std::isnan(stability_code) ? 0 : int(stability_code);
      const int kind = std::isnan(stability_code) ? 3 : code & 1 ? 1 : (code ? 2 : 0);
      const double which = r.rows[p][i + part];
      points << fmt::format("{} {} {} {} {}\n", shifted(v, which == 0 ? -1 : 1), r.rows[p][i + omega], kind, which, v);
    }
    // a bright branch in a model parameter (its rows' omega_b fixed, not the parameter): no band edge drawn
    const bool in_omega = !bright || r.rows[p].empty() || r.rows[p][index_of(r.row_names, "omega_b")] == r.rows[p][omega];
    const double t = r.scalars[turning * r.points + p],
                 e = in_omega ? r.scalars[edge * r.points + p] : std::numeric_limits<double>::quiet_NaN();
    marks << fmt::format("{} {} {}\n", v, std::isfinite(t) ? fmt::format("{}", t) : "NaN", std::isfinite(e) ? fmt::format("{}", e) : "NaN");
  }
  write_file_atomic(dir, stem + ".dat", points.str());
  write_file_atomic(dir, stem + "_marks.dat", marks.str());
  std::vector<std::string> files{stem + ".dat", stem + "_marks.dat"};
  const auto [lo, hi] = std::minmax_element(x.values.begin(), x.values.end());
  const std::string x_name = gnuplot_text(x.parameter);
  // The band edge is known at the axis values only: a mark at each (a line between them invented
  // the values in between).
  std::ostringstream gp;
  const std::string family = bright ? "Bright" : "Dark";
  gp << "# " << family << "-breather branches in the (" << x_name << ", " << y_column << ") plane from " << gnuplot_string(c.output.filename().string())
     << ". Re-run: gnuplot " << gnuplot_file_name(stem + ".gp") << "\n"
     << "if (!exists(\"outfile\")) outfile = " << gnuplot_file_name(stem + ".png") << "\n"
     << "set terminal pngcairo size 1000,700 noenhanced\nset output outfile\n"
     << "set xlabel '" << x_name << " (points left of each value: before the first turning point; right: after)'\n"
     << "set ylabel '" << (bright ? "omega_b, or the model parameter continued" : "omega_b") << "'\nset key outside right top\nset grid\n"
     << (x_log ? "set logscale x\n" : "")
     << fmt::format("set xrange [{}:{}]\n", shifted(*lo, -3), shifted(*hi, 3))
     << axis_value_tics(x.values)
     << "set title '" << gnuplot_text(c.name) << ": " << (bright ? "bright" : "dark") << "-breather branches and their Floquet stability'\n"
     << "plot " << gnuplot_file_name(stem + ".dat") << " using 1:($3 == 0 ? $2 : 1/0) with points pointtype 7 pointsize 0.5 lc rgb '#009900' title 'stable', \\\n"
     << "     '' using 1:($3 == 1 ? $2 : 1/0) with points pointtype 7 pointsize 0.5 lc rgb '#dd0000' title 'real-unstable', \\\n"
     << "     '' using 1:($3 == 2 ? $2 : 1/0) with points pointtype 7 pointsize 0.5 lc rgb '#0000dd' title 'oscillatory-unstable', \\\n"
     << (bright ? "     '' using 1:($3 == 3 ? $2 : 1/0) with points pointtype 6 pointsize 0.5 lc rgb 'gray40' title 'no Floquet', \\\n" : "")
     << "     " << gnuplot_file_name(stem + "_marks.dat") << " using 1:2 with points pointtype 2 pointsize 2 lw 2 lc rgb 'black' title 'turning point', \\\n"
     << "     '' using 1:3 with points pointtype '—' pointsize 2 lc rgb 'gray40' title '"
     << (bright ? "band edge omega" : "band edge omega(pi)") << "'\n";
  draw_figures(dir, {{stem + ".gp", gp.str(), stem + ".png"}}, files);
  return files;
}

std::vector<std::string> write_requested_figure(const SweepConfig& c, const Job& job) {
  if (c.figure.empty()) return {};
  const SweepResults results = read_results(c.output, c, job);
  const std::vector<std::string> files = sweep_figure_files(c);
  mark_side_files_pending(c, files);
  std::vector<std::string> written = draws_stability_figure(c)
                                         ? write_stability_figure(c, results)
                                         : write_sweep_figures(c, job, results, c.figure);
  record_side_files(c, files);
  return written;
}

}  // namespace lrchain::jobs::sweep

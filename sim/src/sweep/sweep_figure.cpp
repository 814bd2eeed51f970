// log10(scalar) over a two-axis grid, focusing boundaries and the fitted detuning exponent
// (sweep/sweep_figure.hpp).
#include "lrchain/sim/sweep/sweep_figure.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include <fmt/format.h>

#include "lrchain/errors.hpp"
#include "lrchain/regime/focusing_intervals.hpp"
#include "lrchain/sim/experiment_config.hpp"
#include "lrchain/sim/least_squares.hpp"
#include "lrchain/sim/output_files.hpp"

namespace lrchain::sim::sweep {

namespace {

// The theta values where a focusing interval of the base config's chain begins or ends.
std::vector<double> focusing_boundaries(const Job& job) {
  const BrightRunConfig b = load_experiment_config(job.base()).bright;
  std::vector<double> ends;
  for (const auto& i : regime::focusing_intervals(b.params, b.branch)) {
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

}  // namespace

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
  const bool y_log = std::all_of(y.values.begin(), y.values.end(), [&](double v) { return y_negative ? v < 0 : v > 0; }) &&
                     std::abs(y.values.back() / y.values.front()) >= 10;
  const double sign = y_negative ? -1.0 : 1.0;  // of the values drawn
  const std::string stem = c.output.stem().string() + "_" + scalar;
  const std::filesystem::path dir = c.output.has_parent_path() ? c.output.parent_path() : std::filesystem::path(".");

  std::ostringstream data;
  data << "# " << x.parameter << ' ' << (y_negative ? "-" : "") << y.parameter << " log10(" << scalar << ")\n";
  for (std::size_t i = 0; i < x.values.size(); ++i) {
    for (std::size_t j = 0; j < y.values.size(); ++j) {
      const double v = r.scalars[s * r.points + i * y.values.size() + j];
      data << fmt::format("{} {} {}\n", x.values[i], y_negative ? -y.values[j] : y.values[j],
                          v > 0 && std::isfinite(v) ? fmt::format("{}", std::log10(v)) : std::string("NaN"));
    }
    data << '\n';
  }
  write_file_atomic(dir, stem + ".dat", data.str());
  std::vector<std::string> files{stem + ".dat"};

  std::ostringstream gp;
  gp << "# log10(" << scalar << ") over (" << x.parameter << ", " << y.parameter << ") from " << c.output.filename().string()
     << ". Re-run: gnuplot " << stem << ".gp\n"
     << "if (!exists(\"outfile\")) outfile = '" << stem << ".png'\n"
     << "set terminal pngcairo size 900,640 noenhanced\nset output outfile\n"
     << "set xlabel '" << x.parameter << "'\nset ylabel '" << (y_negative ? "|" + y.parameter + "|" : y.parameter) << "'\n"
     << "set cblabel 'log10(" << scalar << ")'\nset palette rgbformulae 33,13,10\nset view map\n"
     << (y_log ? "set logscale y\nset format y '1e%L'\n" : "")
     << fmt::format("set yrange [{}:{}]\n", std::min(sign * y.values.front(), sign * y.values.back()),
                    std::max(sign * y.values.front(), sign * y.values.back()))
     << "set title '" << c.name << ": log10(" << scalar
     << "); dashed: focusing interval ends'\n";
  const bool theta_axis = c.job == "bright" && x.parameter == "bright.theta";
  if (theta_axis)
    for (double b : focusing_boundaries(job))
      if (b >= std::min(x.values.front(), x.values.back()) && b <= std::max(x.values.front(), x.values.back()))
        gp << fmt::format("set arrow from {0}, graph 0 to {0}, graph 1 nohead dashtype 2 linewidth 2 front\n", b);
  gp << "set xrange [" << std::min(x.values.front(), x.values.back()) << ":" << std::max(x.values.front(), x.values.back())
     << "]\nsplot '" << stem << ".dat' using 1:2:3 with pm3d notitle\n";
  std::vector<FigureScript> figures{{stem + ".gp", gp.str(), stem + ".png"}};

  if (theta_axis && y.parameter == "bright.detuning" && y_log) {
    const auto p = fitted_exponents(x, y, r, s);
    std::ostringstream csv;
    csv << x.parameter << ",exponent\n";
    for (std::size_t i = 0; i < p.size(); ++i) csv << fmt::format("{},{}\n", x.values[i], p[i]);
    write_file_atomic(dir, stem + "_exponent.csv", csv.str());
    files.push_back(stem + "_exponent.csv");
    std::ostringstream g2;
    g2 << "# Exponent p of " << scalar << " ~ |detuning|^p fitted per theta. Re-run: gnuplot " << stem << "_exponent.gp\n"
       << "if (!exists(\"outfile\")) outfile = '" << stem << "_exponent.png'\n"
       << "set terminal pngcairo size 800,500 noenhanced\nset output outfile\nset datafile separator ','\n"
       << "set xlabel '" << x.parameter << "'\nset ylabel 'p in " << scalar << " ~ |detuning|^p'\nset grid\n"
       << "plot '" << stem << "_exponent.csv' using 1:2 every ::1 with linespoints pointtype 7 notitle\n";
    figures.push_back({stem + "_exponent.gp", g2.str(), stem + "_exponent.png"});
  }
  Figures drawn(dir);
  drawn.draw_all(figures);
  for (const auto& f : figures) files.push_back(f.script);
  for (const auto& png : drawn.drawn()) files.push_back(png);
  if (!drawn.warning().empty()) fmt::print(stderr, "{}\n", drawn.warning());
  return files;
}

}  // namespace lrchain::sim::sweep

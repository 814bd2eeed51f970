// Output files and gnuplot figures of a bright-breather run (Figs. 6-13 style).
#include "lrchain/jobs/simulate/bright_outputs.hpp"
#include "lrchain/provenance_json.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>

#include "lrchain/jobs/figure_format.hpp"
#include "lrchain/jobs/output_files.hpp"
#include "lrchain/sim/strain_sites.hpp"
#include "run_figures.hpp"
#include "run_json.hpp"

namespace lrchain::jobs {

using namespace lrchain::sim;

nlohmann::json to_json(const BrightRunConfig& c, const BrightRunSummary& s) {
  nlohmann::json j;
  j["experiment"] = "bright";
  j["provenance"] = provenance_json();
  j["model"] = model_json(resonant_chain_model(c.params));
  j["branch"] = std::string(to_string(c.branch));
  j["theta"] = c.theta;
  j["sites"] = strain_site_count(c.N);  // n = -N..N, as --sites takes it
  j["periods"] = c.periods;
  j["ansatz_ends"] = c.ansatz_ends;
  j["integrator"] = integrator_json(s.integrator);
  j["step_choice"] = nullptr;
  if (s.step_choice)
    j["step_choice"] = {{"method", "energy-error probe"},
                        {"steps_per_sample", s.step_choice->steps_per_sample},
                        {"largest_linear_frequency", s.step_choice->largest_linear_frequency},
                        {"probe_energy_error", s.step_choice->probe_energy_error},
                        {"probe_runs", s.step_choice->probe_runs},
                        {"probe_seconds", s.step_choice->probe_seconds}};
  j["ansatz"] = {{"omega", s.omega},   {"omega_b", s.omega_b},  {"T_b", s.period},
                 {"group_velocity", s.group_velocity},          {"curvature", s.curvature},
                 {"h_tilde", s.h_tilde}, {"M1", s.M1},          {"M2", s.M2},
                 {"inverse_width", s.inverse_width}};
  j["x0_inf"] = s.x0_inf;
  j["y0_inf"] = s.y0_inf;
  j["max_E_x"] = s.max_Ex;
  j["max_E_y"] = s.max_Ey;
  if (c.error_window_end > 0)
    j["error_window"] = {{"t_max", c.error_window_end}, {"max_E_x", s.max_Ex_window},
                         {"max_E_y", s.max_Ey_window}};
  j["final_E_x"] = s.final_Ex;
  j["final_E_y"] = s.final_Ey;
  j["energy0"] = s.energy0;
  if (!c.ansatz_ends) j["max_relative_energy_drift"] = s.max_energy_drift;
  j["centre_speed"] = s.centre_speed;
  j["centre_start"] = s.centre_start;
  j["centre_end"] = s.centre_end;
  if (c.trailing.fit_start > 0) {
    const auto found = [&s](const nlohmann::json& v) { return s.trailing.found ? v : nlohmann::json(nullptr); };
    j["trailing_structure"] = {{"found", s.trailing.found},
                               {"fit_start", c.trailing.fit_start},
                               {"speed", found(s.trailing.speed)},
                               {"centre_end", found(s.trailing.centre_end)},
                               {"max_energy_density", found(s.trailing.max_energy_density)},
                               {"max_abs_x", found(s.trailing.max_abs_x)},
                               {"y_over_x", found(s.trailing.y_over_x)},
                               {"branch", found(s.trailing.y_over_x < 0 ? "optical" : "acoustic")}};
  }
  add_run_status(j, s.t_end, s.interrupted, s.blew_up, s.stats, s.solve_seconds, s.blow_up);
  return j;
}

namespace {

std::string snapshots_script(const BrightRunResult& r) {
  std::string files, titles;
  for (const auto& s : r.record.snapshots) {
    files += "snapshot_" + s.tag + ".csv ";
    titles += fmt::format("t={:.1f} ", s.t);
  }
  const auto& series = r.record.series;
  const std::size_t rows = series.rows();
  const double t_end = rows > 0 ? series.at(rows - 1, 0) : 0.0;
  // Early times on their own scale (Fig. 8's inset: the error stays below 3 % for t <= 150).
  double max_to_150 = 0;
  for (std::size_t k = 0; k < rows; ++k)
    if (series.at(k, 0) <= 150)
      for (std::size_t column : {1, 2})
        if (std::isfinite(series.at(k, column))) max_to_150 = std::max(max_to_150, series.at(k, column));
  // 0 to 6 % when the errors up to t = 150 fit (the 3 % line at half height), else gnuplot's range.
  const bool percent_scale = max_to_150 < 0.05;
  // A long run gets the early times as a panel of its own right of E_x, E_y (an inset over the
  // curves hid them where it lay).
  const bool early_panel = t_end > 400;
  const std::string errors_size = early_panel ? "set size 0.64,0.333\n" : "";
  const std::string early =
      early_panel
          ? fmt::format("set origin 0.64,0\nset size 0.36,0.333\n"
                        "unset key\nset xrange [0:200]\nset yrange [0:{}]\nset ytics {}\n"
                        "set ylabel ''\n"
                        "set title 'E_x, E_y for t ≤ 200 (dotted: 3 % and t = 150)'\n"
                        "set arrow 21 from 150, graph 0 to 150, graph 1 nohead dt 3 lc rgb 'black'\n"
                        "plot 'series.csv' using 1:2 skip 1 with lines lw 1.5 lc rgb 'red', "
                        "'series.csv' using 1:3 skip 1 with lines dt 2 lw 1.5 lc rgb 'blue', "
                        "0.03 with lines dt 3 lc rgb 'black'\n",
                        percent_scale ? "0.06" : "*", percent_scale ? "0.03" : "autofreq")
          : "";
  return fmt::format(R"GP(# Snapshots of x_n, y_n (lattice, solid lines) vs the NLS ansatz eq. (38) (black dashed), and E_x, E_y.
if (!exists("outfile")) outfile = 'snapshots.png'
set terminal pngcairo size 1400,1100 font ",11"
set output outfile
set datafile separator ","
files = "{}"
titles = "{}"
set key outside right
set multiplot
set size 1,0.333
set origin 0,0.667
set xlabel "site n"
set ylabel "x_n (dimensionless)"
plot for [i=1:words(files)] word(files,i) using 1:2 with lines lw 2 title "lattice ".word(titles,i), \
     for [i=1:words(files)] word(files,i) using 1:4 with lines dt 2 lw 0.8 lc rgb "black" title (i==1 ? "ansatz" : "")
set origin 0,0.333
set ylabel "y_n (dimensionless)"
plot for [i=1:words(files)] word(files,i) using 1:3 with lines lw 2 title "lattice ".word(titles,i), \
     for [i=1:words(files)] word(files,i) using 1:5 with lines dt 2 lw 0.8 lc rgb "black" title (i==1 ? "ansatz" : "")
set origin 0,0
{}set xlabel "t (dimensionless)"
set ylabel "relative error E_x, E_y"
plot 'series.csv' using 1:2 skip 1 with lines lw 1.5 lc rgb "red" title "E_x", \
     'series.csv' using 1:3 skip 1 with lines dt 2 lw 1.5 lc rgb "blue" title "E_y"
{}unset multiplot
)GP",
                     files, titles, errors_size, early);
}

std::string energy_script(const BrightRunResult& r) {
  const float emax = largest_energy_density(r.record);
  const std::string every = r.record.fields.empty() ? "" : image_every(r.record.fields.front());
  return fmt::format(R"GP(# Left: energy density e_n(t) (eq. (40)), log colour scale. Right: energy centre X(t) (eq. (41)).
{}set autoscale fix
plot 'energy_density_spacetime.bin' binary matrix {}using 1:2:($3 > {:.3e} ? $3 : {:.3e}) with image notitle
unset logscale cb
set datafile separator ","
unset cblabel
set lmargin at screen 0.57
set rmargin at screen 0.97
set xlabel "t (dimensionless)"
set ylabel "energy centre X, eq. (41) (sites)" noenhanced
# t over the run, X with room above and below (its ends lay on the frame's corners)
set autoscale xfix
set autoscale y
set offsets 0, 0, graph 0.05, graph 0.05
plot 'series.csv' using 1:5 skip 1 with lines lw 1.5 notitle
unset multiplot
)GP",
                     log_energy_panel_head(600, emax * 1e-6, emax), every, emax * 1e-6, emax * 1e-6);
}

}  // namespace

std::vector<std::string> write_bright_outputs(const std::filesystem::path& dir,
                                              const BrightRunResult& r,
                                              const nlohmann::json& summary, bool draw_figures) {
  return write_run_outputs(dir, r.record, summary.dump(2),
                           {{"snapshots.gp", snapshots_script(r), "snapshots.png"},
                            {"energy.gp", energy_script(r), "energy.png"}},
                           draw_figures);
}

}  // namespace lrchain::jobs

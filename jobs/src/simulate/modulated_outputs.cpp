// JSON summary, data files and gnuplot figures of the modulated wave (experiment 7, Sec. 5.1; Fig. 16).
#include "lrchain/jobs/simulate/modulated_outputs.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "lrchain/model_json.hpp"
#include "lrchain/provenance_json.hpp"
#include "lrchain/jobs/figure_format.hpp"
#include "lrchain/jobs/output_files.hpp"
#include "run_figures.hpp"
#include "run_json.hpp"

namespace lrchain::jobs {

using namespace lrchain::sim;

nlohmann::json to_json(const ModulatedRunConfig& c, const ModulatedRunSummary& s) {
  nlohmann::json j;
  j["experiment"] = "modulated";
  j["provenance"] = provenance_json();
  j["name"] = c.name;
  j["model"] = model_json(resonant_chain_model(c.params));
  j["sites"] = c.N;
  j["initial"] = {{"epsilon", c.epsilon}, {"theta0", s.theta0}, {"omega", s.omega}, {"modulation_depth", c.b}};
  j["integrator"] = integrator_json(c.integrator);
  j["group_velocity"] = s.group_velocity;
  j["t_start"] = s.t_start;
  j["initial_contrast"] = s.initial_contrast;
  j["contrast_threshold"] = c.contrast_threshold;
  j["instability_time"] = s.instability_time ? nlohmann::json(*s.instability_time) : nlohmann::json(nullptr);
  j["dark_speed"] = s.dark_samples >= 2 ? nlohmann::json(s.dark_speed) : nlohmann::json(nullptr);  // fit needs 2
  j["dark_speed_fit"] = {c.speed_fit_start, c.speed_fit_end};
  j["dark_samples"] = s.dark_samples;
  j["energy0"] = s.energy0;
  j["max_relative_energy_drift"] = s.max_energy_drift;
  j["checkpoints_written"] = s.checkpoints_written;
  if (!c.checkpoint_file.empty()) j["checkpoint_file"] = c.checkpoint_file;
  add_run_status(j, s.t_end, s.interrupted, s.blew_up, s.stats, s.solve_seconds, s.blow_up);
  return j;
}

namespace {

std::string modulated_energy_script(const ModulatedRunResult& r, const nlohmann::json& summary) {
  double sum = 0, count = 0;
  for (const auto& f : r.record.fields)
    for (float v : f.values) { sum += v; count += 1; }
  const double emean = count > 0 && sum > 0 ? sum / count : 1;
  const double threshold = summary.value("contrast_threshold", 0.2);
  // The onset of the modulational instability: the first time the contrast exceeds the threshold.
  std::string onset;
  if (summary.contains("instability_time") && summary["instability_time"].is_number())
    onset = fmt::format("set arrow from {0}, graph 0 to {0}, graph 1 nohead dt 3 lw 1.5 lc rgb 'dark-green' front\n"
                        "set label 'onset t = {0:.0f}' at {0}, graph 0.93 offset 0.5,0 tc rgb 'dark-green' front\n",
                        summary["instability_time"].get<double>());
  return fmt::format(R"GP(# Energy density e_n(t) (eq. (40)) on the periodic chain (Fig. 16 bottom right), and the
# contrast (max-min)/mean of the running-mean e_n with the position of its minimum (dark-breather centre);
# dashed: the contrast threshold, dotted: the onset time (first contrast above it).
if (!exists("outfile")) outfile = 'energy.png'
set terminal pngcairo size 1400,700 font ",11"
set output outfile
set multiplot layout 1,2
set xlabel "site n"
set ylabel "t (dimensionless)"
{}
set cblabel "energy density e_{{n}}, eq. (40)"
set rmargin at screen 0.40
set cbrange [0:{:.3e}]
# both panels with room below for the right panel's legend (there it hides none of its points)
set bmargin 6
set autoscale fix
plot 'energy_density_spacetime.bin' binary matrix {}with image notitle
unset cblabel
set lmargin at screen 0.57
set rmargin at screen 0.92
set autoscale
set datafile separator ","
set xlabel "t (dimensionless)"
set ylabel "contrast (max e - min e)/mean e"
set y2label "site of the minimum of e_{{n}}"
set y2tics
set ytics nomirror
set yrange [0:*]
set offsets 0, 0, graph 0.05, 0
set key below center horizontal box
{}plot 'series.csv' using 1:3 skip 1 with lines lw 1.2 title "contrast", \
     {:g} with lines dt 2 lw 1.5 lc rgb "black" title "threshold {:g}", \
     'series.csv' using 1:4 skip 1 axes x1y2 with points pt 7 ps 0.2 lc rgb "red" title "min-e site"
unset multiplot
)GP",
                     viridis_palette, 2 * emean,
                     r.record.fields.empty() ? "" : image_every(r.record.fields.front()), onset, threshold, threshold);
}

std::string modulated_snapshots_script(const ModulatedRunResult& r) {
  std::string body;
  for (const auto& s : r.record.snapshots)
    body += fmt::format("set title \"t = {:.0f}\"\nplot 'snapshot_{}.csv' using 1:4 skip 1 with linespoints pt 7 ps 0.3 lw 0.8 notitle\n",
                        s.t, s.tag);
  return velocity_snapshots_script("Fig. 16", 330, r.record.snapshots.size(), body);
}

}  // namespace

std::vector<std::string> write_modulated_outputs(const std::string& dir, const ModulatedRunResult& r,
                                                 const nlohmann::json& summary, bool draw_figures) {
  std::vector<FigureScript> figures = {{"energy.gp", modulated_energy_script(r, summary), "energy.png"}};
  if (!r.record.snapshots.empty())
    figures.push_back({"snapshots.gp", modulated_snapshots_script(r), "snapshots.png"});
  return write_run_outputs(dir, r.record, summary.dump(2), figures, draw_figures);
}

}  // namespace lrchain::jobs

// JSON summary, data files and gnuplot figures of the driven chain (experiment 6, Sec. 4.3; Figs. 14, 15).
#include "lrchain/jobs/simulate/drive_outputs.hpp"

#include <algorithm>

#include <fmt/format.h>

#include "lrchain/model_json.hpp"
#include "lrchain/provenance_json.hpp"
#include "lrchain/jobs/figure_format.hpp"
#include "lrchain/jobs/output_files.hpp"
#include "run_figures.hpp"
#include "run_json.hpp"

namespace lrchain::jobs {

using namespace lrchain::sim;

nlohmann::json to_json(const DriveRunConfig& c, const DriveRunSummary& s) {
  nlohmann::json j;
  j["experiment"] = "drive";
  j["provenance"] = provenance_json();
  j["model"] = model_json(resonant_chain_model(c.params));
  j["sites"] = c.beads;
  j["drive"] = {{"amplitude", c.amplitude}, {"omega0", c.omega0}, {"ramp_rate", c.ramp_rate},
                {"switch_off_time", c.t_m}};
  j["integrator"] = integrator_json(c.integrator);
  j["theta"] = s.theta;
  j["group_velocity"] = s.group_velocity;
  j["front_speed"] = s.front_samples >= 2 ? nlohmann::json(s.front_speed) : nlohmann::json(nullptr);
  j["front_fit"] = {c.front_fit_start, c.front_fit_end};
  j["final_participation"] = s.final_participation;
  j["max_participation"] = s.max_participation;
  j["final_peaks"] = s.final_peaks;
  j["final_energy"] = s.final_energy;
  j["max_energy"] = s.max_energy;
  add_run_status(j, s.t_end, s.interrupted, s.blew_up, s.stats, s.solve_seconds, s.blow_up);
  return j;
}

namespace {

std::string drive_energy_script(const DriveRunResult& r) {
  const float emax = largest_energy_density(r.record);
  return fmt::format(R"GP(# Energy density e_n(t) (eq. (40)) of the driven chain (Fig. 14 left), with n = c_+ t
# (dashed), and the front of the wave pattern (right).
{}set xrange [1:{:.1f}]
set yrange [0:{:.1f}]
# a dark legend box, on which the white dashed line shows (an opaque white box hid it)
set key top right opaque fc rgb "#404040" box lc rgb "white" textcolor rgb "white"
plot 'energy_density_spacetime.bin' binary matrix {}using 1:2:($3 > {:.3e} ? $3 : {:.3e}) with image notitle, \
     (x/{:.6f}) with lines dt 2 lw 2 lc rgb "white" title "n = c_+ t"
unset logscale cb
unset cblabel
set lmargin at screen 0.57
set rmargin at screen 0.97
set autoscale
set datafile separator ","
set xlabel "t (dimensionless)"
set ylabel "front site n, participation number"
set key top left noopaque nobox textcolor rgb "black"
plot 'series.csv' using 1:3 skip 1 with lines lw 1.5 title "front", \
     'series.csv' using 1:4 skip 1 with lines lw 1.5 title "participation (sum e)^2/sum e^2", \
     {:.6f}*x with lines dt 2 lc rgb "black" title "c_+ t"
unset multiplot
)GP",
                     log_energy_panel_head(650, emax * 1e-5, emax),
                     double(r.record.fields.empty() ? 1 : r.record.fields[0].sites), r.summary.t_end,
                     r.record.fields.empty() ? "" : image_every(r.record.fields.front()), emax * 1e-5, emax * 1e-5, r.summary.group_velocity, r.summary.group_velocity);
}

std::string drive_snapshots_script(const DriveRunResult& r) {
  std::string body;
  for (const auto& s : r.record.snapshots)
    body += fmt::format("set title \"t = {:.1f}\"\nplot 'snapshot_{}.csv' using 1:4 skip 1 with lines lw 1 notitle\n",
                        s.t, s.tag);
  return velocity_snapshots_script("Fig. 15", 350, r.record.snapshots.size(), body);
}

}  // namespace

std::vector<std::string> write_drive_outputs(const std::string& dir, const DriveRunResult& r,
                                             const nlohmann::json& summary, bool draw_figures) {
  std::vector<FigureScript> figures = {{"energy.gp", drive_energy_script(r), "energy.png"}};
  if (!r.record.snapshots.empty())
    figures.push_back({"snapshots.gp", drive_snapshots_script(r), "snapshots.png"});
  return write_run_outputs(dir, r.record, summary.dump(2), figures, draw_figures);
}

}  // namespace lrchain::jobs

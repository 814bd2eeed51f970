// gnuplot script pieces of the run figures (run_figures.hpp).
#include "run_figures.hpp"

#include <algorithm>

#include <fmt/format.h>

#include "lrchain/jobs/figure_format.hpp"

namespace lrchain::jobs {

float largest_energy_density(const sim::RunRecord& record) {
  float emax = 0;
  for (const auto& f : record.fields)
    for (float v : f.values) emax = std::max(emax, v);
  return emax > 0 ? emax : 1;
}

std::string log_energy_panel_head(int height, double low, double high) {
  return fmt::format(R"GP(if (!exists("outfile")) outfile = 'energy.png'
set terminal pngcairo size 1400,{} font ",11"
set output outfile
set multiplot layout 1,2
set xlabel "site n"
set ylabel "t (dimensionless)"
set logscale cb
set cbrange [{:.3e}:{:.3e}]
{}
set cblabel "energy density e_{{n}}, eq. (40)"
set rmargin at screen 0.40
set format cb "%.0e"
)GP",
                     height, low, high, jobs::viridis_palette);
}

std::string velocity_snapshots_script(const std::string& figure, std::size_t row_height, std::size_t snapshots,
                                      const std::string& body) {
  const std::size_t k = std::max<std::size_t>(1, snapshots);
  return fmt::format(R"GP(# Bead velocities du_n/dt at the snapshot times ({}).
if (!exists("outfile")) outfile = 'snapshots.png'
set terminal pngcairo size 1400,{} font ",11"
set output outfile
set datafile separator ","
set multiplot layout {},1
set xlabel "site n"
set ylabel "bead velocity du_n/dt"
set offsets 0, 0, graph 0.05, graph 0.05
{}unset multiplot
)GP",
                     figure, row_height * k, k, body);
}

}  // namespace lrchain::jobs

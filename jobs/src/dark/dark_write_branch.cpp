// The branch's files (`lrchain dark continue --out`): branch.csv (one row per point: measures,
// stability, Floquet moduli), floquet_moduli.csv (every multiplier off the unit circle) and figures.
#include <algorithm>
#include <cmath>
#include <sstream>

#include <fmt/format.h>

#include "dark_steps.hpp"
#include "lrchain/jobs/gnuplot_text.hpp"

namespace lrchain::jobs::dark {

using namespace lrchain::sim::dark;

void write_branch(const DarkResult& r, const std::string& dir, jobs::Figures& figures) {
  const DarkConfig& c = r.config;
  const bool model_points = r.model_file();  // also the contact changes per period
  std::ostringstream csv;
  const bool in_parameter = c.parameter != "omega_b";  // the continued model parameter first
  csv << (in_parameter ? c.parameter + "," : std::string()) << "omega_b,norm_squared,K_x,K_y,C_x,C_y,E_b,stability,max_modulus,max_real,max_period_doubling,"
         "max_oscillatory,iterations" << (model_points ? ",contact_changes_per_period" : "") << "\n";
  std::ostringstream mult;  // omega_b, |lambda|, type (0 complex, 1 real>0, 2 real<0)
  mult << (in_parameter ? c.parameter : std::string("omega_b")) << ",modulus,type,branch_part\n";
  int part = 0;
  bool unstable_in[2] = {false, false};  // a modulus > 1 before / after the first turning point
  double last_tangent = -1;
  for (const BranchPoint& b : r.branch.points) {
    if ((b.tangent_omega > 0) != (last_tangent > 0)) ++part;
    last_tangent = b.tangent_omega;
    if (in_parameter) csv << fmt::format("{:.12g},", b.parameter);
    csv << fmt::format("{:.12g},{:.12g},{:.12g},{:.12g},{:.6g},{:.6g},{:.3g},{},{:.12g},{:.12g},{:.12g},{:.12g},{}",
                       b.omega_b, b.measures.norm_squared, b.measures.K_x, b.measures.K_y, b.measures.C_x,
                       b.measures.C_y, b.measures.E_b, b.floquet.kind(), b.floquet.max_modulus,
                       b.floquet.max_real, b.floquet.max_period_doubling, b.floquet.max_oscillatory,
                       b.iterations);
    if (model_points)  // empty for a smooth model
      csv << "," << (b.contact_changes_per_period ? std::to_string(*b.contact_changes_per_period) : std::string());
    csv << "\n";
    for (auto l : b.floquet.multipliers) {
      if (std::abs(l) < 1.0 + 1e-6) continue;
      const bool real = std::abs(l.imag()) <= 1e-7 * std::abs(l);
      mult << fmt::format("{:.12g},{:.12g},{},{}\n", in_parameter ? b.parameter : b.omega_b, std::abs(l), real ? (l.real() > 0 ? 1 : 2) : 0, part);
      unstable_in[part >= 1] = true;
    }
  }
  jobs::write_file_atomic(dir, "branch.csv", csv.str());
  jobs::write_file_atomic(dir, "floquet_moduli.csv", mult.str());
  std::ostringstream folds;  // the turning points, interpolated between the points on either side
  folds << c.parameter << ",norm_squared,after_point,fraction\n";
  for (const FoldPoint& f : r.branch.folds)
    folds << fmt::format("{:.12g},{:.12g},{},{:.6g}\n", f.omega_b, f.norm_squared, f.after, f.fraction);
  jobs::write_file_atomic(dir, "folds.csv", folds.str());
  // The figures' titles name the branch the breathers bifurcate from (a model's own branch name).
  const std::string branch = jobs::gnuplot_text(r.edge.branch, jobs::GnuplotTextMode::enhanced);
  const std::string label = jobs::gnuplot_text(lattice_label(r), jobs::GnuplotTextMode::enhanced);
  if (in_parameter) {  // a model parameter at fixed omega_b: the norm over the parameter
    figures.draw({"branch.gp",
                  fmt::format("if (!exists(\"outfile\")) outfile = 'branch.png'\n"
                              "set terminal pngcairo size 900,650\nset output outfile\n"
                              "set datafile separator ','\nset xlabel '{0}'\n"
                              "set ylabel 'renormalised ℓ^{{2}} norm squared'\nset key below\n"
                              "set offsets graph 0.03, graph 0.03, graph 0.05, graph 0.05\n"
                              "set title '{1} dark breathers at ω_{{b}} = {2:.6g}, {3} (red: real instability)'\n"
                              "plot 'branch.csv' skip 1 u 1:3 w lp pt 7 ps 0.6 lc 'blue' t 'branch', "
                              "'' skip 1 u 1:(strstrt(strcol(9),'real') > 0 ? $3 : 1/0) w p pt 7 lc 'red' t 'real instability'\n",
                              jobs::gnuplot_text(c.parameter, jobs::GnuplotTextMode::enhanced), branch, c.omega_b, label),
                  "branch.png"});
    return;
  }
  // The x range holds the band edge (its line inside the frame) and every point, on whichever side
  // of the edge the branch lies (below it for the resonant chain, above it where h_tilde > 0).
  const double omega_edge = r.edge.omega;
  double lowest = omega_edge, highest = omega_edge;
  for (const auto& b : r.branch.points) {
    lowest = std::min(lowest, b.omega_b);
    highest = std::max(highest, b.omega_b);
  }
  const double margin = 0.03 * std::max(highest - lowest, 1e-3);
  const bool above_edge = highest > omega_edge;  // the edge's label goes on the side away from the points
  // eq. (51) is the resonant chain's measure; a model's sums the same over its lattice variables.
  const std::string norm_label = model_points ? "renormalised ℓ^{2} norm squared Σ_{n,v} (K_v^2 − (z_{v,n}(0) − C_v)^2)"
                                              : "renormalised ℓ^{2} norm squared, eq. (51)";
  figures.draw({"branch.gp",
                fmt::format("if (!exists(\"outfile\")) outfile = 'branch.png'\n"
                            "set terminal pngcairo size 900,650\nset output outfile\n"
                            "set datafile separator ','\nset xlabel 'breather frequency ω_{{b}}'\n"
                            "set ylabel '{6}'\n"
                            "set xrange [{4:.8g}:{5:.8g}]\nset key below\nset offsets 0, 0, graph 0.05, graph 0.05\n"
                            "set arrow from {0},graph 0 to {0},graph 1 nohead lc 'black'\n"
                            "set label 'band edge {0:.4f}' at {0},graph 0.96 {7}\n"
                            "set title '{1} {2}-centred dark breathers, {3} (red: real instability)'\n"
                            "plot 'branch.csv' skip 1 u 1:2 w l lc 'blue' t 'branch', "
                            "'' skip 1 u 1:(strstrt(strcol(8),'real') > 0 ? $2 : 1/0) w p pt 7 lc 'red' t 'real instability'\n",
                            omega_edge, branch, c.center, label, lowest - margin, highest + margin, norm_label,
                            above_edge ? "left offset 0.5,0" : "right offset -0.5,0"),
                "branch.png"});
  // One panel per part of the branch that was computed (before / after the first turning point);
  // a part without multipliers off the unit circle says so instead of showing an empty frame.
  // Grey: the band next to 1 where the symmetry multipliers lie, which the stability does not count.
  const bool turned = part >= 1;
  const double symmetry_band = sim::dark::FloquetOptions{}.symmetry_tolerance;
  // Every panel over the branch's omega_b (3 % beyond its ends, at least 1e-6), the tics with the
  // decimals that tell them apart (a branch that moved 2e-6 in omega_b had its tics all "1.002000").
  double first = r.branch.points.empty() ? omega_edge : r.branch.points.front().omega_b, last = first;
  for (const auto& b : r.branch.points) {
    first = std::min(first, b.omega_b);
    last = std::max(last, b.omega_b);
  }
  const double spread = std::max(last - first, 1e-6 * std::max(1.0, std::abs(first)));
  const int decimals = std::max(0, int(std::ceil(-std::log10(spread))) + 1);
  std::string moduli = fmt::format(
      "if (!exists(\"outfile\")) outfile = 'floquet_moduli.png'\n"
      "set terminal pngcairo size 1000,{3}\nset output outfile\n"
      "set datafile separator ','\nset xlabel 'breather frequency ω_{{b}}'\nset ylabel 'Floquet modulus |λ|'\n"
      "set xrange [{6:.12g}:{7:.12g}]\nset format x '%.{8}f'\n"
      // Room below the lowest modulus as above the highest (a modulus next to 1 lay on the frame),
      // the y range not widened to the next tic.
      "set offsets 0, 0, graph 0.1, graph 0.05\nset autoscale yfix\nset key off\n"
      "set object 1 rectangle from graph 0, first 1 to graph 1, first {5:.6g} behind fillcolor rgb '#e4e4e4' "
      "fillstyle solid noborder\n"
      "set multiplot layout {4},1 title '{0} {1}-centred, {2}: Floquet moduli |λ| > 1 (blue: complex, red: real > 0, "
      "green: real < 0)'\n",
      branch, c.center, label, turned ? 720 : 420, turned ? 2 : 1, 1 + symmetry_band, first - 0.03 * spread,
      last + 0.03 * spread, decimals);
  for (int p = 0; p < (turned ? 2 : 1); ++p) {
    const std::string select = p == 0 ? "$4==0" : "$4>=1";
    moduli += fmt::format("set title \"{}{}\"\n",
                          p == 0 ? "weakly nonlinear (before the turning point)" : "strongly nonlinear (after the turning point)",
                          p == 0 ? fmt::format("\\ngrey: |λ| − 1 ≤ {:g}, where the symmetry multipliers lie (not counted as instability)",
                                               symmetry_band)
                                 : "");
    if (!unstable_in[p]) {
      moduli += "set yrange [0.9:1.1]\nset label 1 'all multipliers on the unit circle: linearly stable' at graph 0.5, graph 0.7 center\n"
                "plot 'branch.csv' skip 1 u 1:(1) w l lc 'grey' dt 2\nunset label 1\nset autoscale yfix\n";
      continue;
    }
    moduli += fmt::format("plot 'floquet_moduli.csv' skip 1 u 1:({0} && $3==0 ? $2 : 1/0) w p pt 7 ps 0.5 lc 'blue', "
                          "'' skip 1 u 1:({0} && $3==1 ? $2 : 1/0) w p pt 13 lc 'red', "
                          "'' skip 1 u 1:({0} && $3==2 ? $2 : 1/0) w p pt 5 lc 'dark-green'\n", select);
  }
  moduli += "unset multiplot\n";
  figures.draw({"floquet_moduli.gp", moduli, "floquet_moduli.png"});
}

}  // namespace lrchain::jobs::dark

// The evolution's files (`lrchain dark evolve --out`, Figs. 21, 22, 25) for any lattice variables:
// <name>_spacetime.bin per variable, evolution.csv, snapshots.csv (n, every v_0, every v_T),
// evolution.gp (snapshots and space-time maps), diagnostics.gp (E_b(t), position), summary.json.
#include <algorithm>
#include <sstream>

#include <fmt/format.h>

#include "dark_steps.hpp"
#include "lrchain/jobs/figure_format.hpp"
#include "lrchain/jobs/gnuplot_text.hpp"
#include "lrchain/sim/run_record.hpp"

namespace lrchain::jobs::dark {

using namespace lrchain::sim::dark;

namespace {

// One lattice variable of an evolution's files: its name (x, r, u0, ...) and axis label.
struct EvolutionVariable {
  std::string name, label;
};

std::string enhanced(const std::string& text) { return jobs::gnuplot_text(text, jobs::GnuplotTextMode::enhanced); }

// The variables with their axis labels, and the figures' title.
std::pair<std::vector<EvolutionVariable>, std::string> evolution_labels(const DarkResult& r) {
  const DarkConfig& c = r.config;
  if (!r.model_file())
    return {{{"x", "strain x_{n}"}, {"y", "strain y_{n}"}},
            fmt::format("{} {}-centred dark breather, ρ = {:.4g}, ω_{{b}} = {:g}", r.edge.branch, c.center,
                        c.params.rho, c.omega_b)};
  std::vector<EvolutionVariable> variables;
  for (std::size_t v = 0; v < r.edge.variables.size(); ++v)
    variables.push_back({r.edge.variables[v], enhanced(r.edge.variable_meanings[v])});
  return {variables, fmt::format("{} {} {}-centred dark breather, ω_{{b}} = {:g}", enhanced(c.model->name()),
                                 enhanced(r.edge.branch), c.center, c.omega_b)};
}

}  // namespace

void write_evolution(const DarkResult& r, const std::string& dir, jobs::Figures& figures, nlohmann::json& summary) {
  const DarkEvolution& e = r.evolution;
  const auto [variables, title] = evolution_labels(r);
  const Index N = e.sites;
  const Index V = Index(variables.size());
  for (Index field = 0; field < V; ++field) {
    sim::SpaceTime st;
    st.quantity = variables[std::size_t(field)].name + "_n";
    st.first_label = -(N - 1) / 2;
    st.sites = N;
    for (std::size_t m = 0; m < e.snapshots.size(); ++m) {
      st.times.push_back(static_cast<double>(m) * e.period);
      for (Index i = 0; i < N; ++i) st.values.push_back(static_cast<float>(e.snapshots[m](field * N + i)));
    }
    jobs::write_spacetime_binary(dir, variables[std::size_t(field)].name + "_spacetime.bin", st);
  }
  std::ostringstream ev;
  ev << "t,E_b,C_x,K_x,position,depth\n";
  for (const auto& p : e.periods)
    ev << fmt::format("{:.12g},{:.6e},{:.9g},{:.9g},{:.6f},{:.6g}\n", p.t, p.E_b, p.C_x, p.K_x, p.position, p.depth);
  jobs::write_file_atomic(dir, "evolution.csv", ev.str());
  const Eigen::VectorXd& z0 = e.snapshots.front();
  const Eigen::VectorXd& zT = e.snapshots.back();
  std::ostringstream sn;
  sn << "n";
  for (const char* when : {"_0", "_T"})
    for (const auto& v : variables) sn << "," << v.name << when;
  sn << "\n";
  for (Index i = 0; i < N; ++i) {
    sn << i - (N - 1) / 2;
    for (const Eigen::VectorXd* z : {&z0, &zT})
      for (Index field = 0; field < V; ++field) sn << fmt::format(",{:.17g}", (*z)(field * N + i));
    sn << "\n";
  }
  jobs::write_file_atomic(dir, "snapshots.csv", sn.str());
  const double T = e.periods.back().t;
  const double nmin = double(-(N - 1) / 2) - 0.5, nmax = double((N - 1) / 2) + 0.5;
  const double height = 0.94 / double(V);
  const char* time_unit = r.model_file() ? "model units" : "dimensionless";  // the chain's of Sec. 2
  std::string maps, snapshots, right;
  for (Index k = 0; k < V; ++k) {
    const EvolutionVariable& v = variables[std::size_t(k)];
    const double origin = double(V - 1 - k) * height;
    const std::string name = enhanced(v.name);  // v.label is enhanced text ("strain x_{n}")
    maps += fmt::format("{}{}_{{n}}(m T_{{b}})", k == 0 ? "" : ", ", name);
    snapshots += fmt::format(
        "set size 0.36,{0:g}\nset origin 0.0,{1:g}\nset ylabel '{2}'\nset title '{3}_{{n}}'\n"
        "plot 'snapshots.csv' skip 1 u 1:{4} w lp pt 3 lc 'red' t 't = 0', '' skip 1 u 1:{5} w lp pt 4 lc 'blue' t 't = {6:.1f}'\n",
        height, origin, v.label, name, 2 + k, 2 + V + k, T);
    right += fmt::format("set size 0.64,{0:g}\nset origin 0.36,{1:g}\nset cblabel '{2}'\n"
                         "set title '{3}_{{n}}(t), t = m T_{{b}}'\n"
                         "plot '{4}_spacetime.bin' binary matrix with image notitle\n",
                         height, origin, v.label, name, v.name);
  }
  figures.draw({
      "evolution.gp",
      fmt::format("if (!exists(\"outfile\")) outfile = 'evolution.png'\n"
                  "set terminal pngcairo size 1500,{5}\nset output outfile\n"
                  "set datafile separator ','\n"
                  "set multiplot title '{0}: snapshots at t = 0 and t = {1:.1f} (left), space-time {6} (right)'\n"
                  "set key outside top center horizontal\nset xlabel 'site n'\n"
                  // the snapshots half a site beyond the end sites and 5 % above and below the
                  // curves (their markers lay on the frame), the maps over the sites' cells
                  "set xrange [{10}:{11}]\nset offsets 0, 0, graph 0.05, graph 0.05\n"
                  "{7}"
                  "set xrange [{2}:{3}]\nset offsets 0, 0, 0, 0\n"
                  "set datafile separator whitespace\n"
                  "set ylabel 't ({9})'\nset yrange [0:{1}]\n"
                  "{4}\nset colorbox\n{8}"
                  "unset multiplot\n",
                  title, T, nmin, nmax, jobs::viridis_palette, 450 * std::max<Index>(V, 2), maps, snapshots, right, time_unit,
                  nmin - 0.5, nmax + 0.5),
      "evolution.png"});
  figures.draw({
      "diagnostics.gp",
      fmt::format("if (!exists(\"outfile\")) outfile = 'diagnostics.png'\n"
                  "set terminal pngcairo size 1000,800\nset output outfile\n"
                  "set datafile separator ','\nset xlabel 't ({1})'\n"
                  "set multiplot layout 2,1 title '{0}'\n"
                  "set logscale y\nset format y '%.0e'\nset ylabel '{2}'\n"
                  "set title 'relative error E_{{b}}(m T_{{b}})'\n"
                  "plot 'evolution.csv' skip 1 u 1:($2 > 1e-16 ? $2 : 1e-16) w l lc 'blue' notitle\n"
                  "unset logscale y\nset format y '%g'\nset ylabel 'site n'\n"
                  "set title 'breather position (amplitude dip over each period; unwrapped)'\n"
                  "plot 'evolution.csv' skip 1 u 1:5 w l lc 'red' notitle\n"
                  "unset multiplot\n",
                  title, time_unit, r.model_file() ? "E_{b}(t) = max|Z(t) − Z(0)| / max|Z(0)|" : "E_{b}(t), eq. (52)"),
      "diagnostics.png"});
  figures.finish(summary);
  jobs::write_file_atomic(dir, "summary.json", summary.dump(2) + "\n");
}

}  // namespace lrchain::jobs::dark

// write(DarkResult, out): the dark job's files — profile and Floquet multipliers (solve, floquet),
// the branch (continue), the evolution (evolve), result.h5 — with their gnuplot figures.
#include <algorithm>
#include <cmath>
#include <sstream>

#include <fmt/format.h>

#include "dark_steps.hpp"
#include "lrchain/jobs/dark_evolution_hdf5.hpp"
#include "lrchain/jobs/model_dark_hdf5.hpp"
#include "lrchain/jobs/dark_hdf5.hpp"
#include "lrchain/jobs/gnuplot_text.hpp"
#include "lrchain/jobs/output_lock.hpp"

namespace lrchain::jobs::dark {

using nlohmann::json;
using namespace lrchain::sim::dark;

std::string lattice_label(const DarkResult& r) {
  return r.model_file() ? r.config.model->name() : fmt::format("ρ = {:.4g}", r.config.params.rho);
}

// profile.csv: n, then Z(0), the seed and Z(T_b) per variable (the chain: x0, y0, x_seed, y_seed,
// x_T, y_T); profile.gp draws them.
void write_profile(const DarkResult& r, const std::string& dir, jobs::Figures& figures) {
  const DarkConfig& c = r.config;
  const Index N = dark_sites(c);
  std::ostringstream os;
  if (!r.model_file()) {
    os << "n,x0,y0,x_seed,y_seed,x_T,y_T\n";
    for (Index i = 0; i < N; ++i)
      os << fmt::format("{},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g}\n", i - (N - 1) / 2, r.z0(i),
                        r.z0(N + i), r.seed(i), r.seed(N + i), r.z_period(i), r.z_period(N + i));
    jobs::write_file_atomic(dir, "profile.csv", os.str());
    // x_n and y_n in panels of their own (drawn together, each hid the other).
    figures.draw({"profile.gp",
                  fmt::format("if (!exists(\"outfile\")) outfile = 'profile.png'\n"
                              "set terminal pngcairo size 1000,900\nset output outfile\n"
                              "set datafile separator ','\nset xlabel 'site n'\nset key outside\n"
                              "set offsets 0, 0, graph 0.05, graph 0.05\n"  // no marker on the frame
                              "set xrange [{2}:{3}]\n"
                              "set multiplot layout 2,1 title 'dark breather ({0} centred), ω_{{b}} = {1:.5f}: Z(0), Z(T_{{b}}), seed eq. (48)'\n"
                              "set ylabel 'strain x_{{n}} (dimensionless)'\n"
                              "plot 'profile.csv' skip 1 u 1:2 w lp pt 3 t 'x_{{n}}(0)', '' skip 1 u 1:6 w p pt 4 ps 1.5 t 'x_{{n}}(T_{{b}})', "
                              "'' skip 1 u 1:4 w p pt 6 t 'x seed'\n"
                              "set ylabel 'strain y_{{n}} (dimensionless)'\n"
                              "plot 'profile.csv' skip 1 u 1:3 w lp pt 3 t 'y_{{n}}(0)', '' skip 1 u 1:7 w p pt 4 ps 1.5 t 'y_{{n}}(T_{{b}})', "
                              "'' skip 1 u 1:5 w p pt 6 t 'y seed'\n"
                              "unset multiplot\n",
                              c.center, c.omega_b, -(N - 1) / 2 - 1, (N - 1) / 2 + 1),
                  "profile.png"});
    return;
  }
  const std::vector<std::string>& variables = r.edge.variables;
  os << "n";
  for (const auto& v : variables) os << "," << v << "_0," << v << "_seed," << v << "_T";
  os << "\n";
  for (Index i = 0; i < N; ++i) {
    os << i - (N - 1) / 2;
    for (std::size_t v = 0; v < variables.size(); ++v) {
      const Index at = Index(v) * N + i;
      os << fmt::format(",{:.17g},{:.17g},{:.17g}", r.z0(at), r.seed(at), r.z_period(at));
    }
    os << "\n";
  }
  jobs::write_file_atomic(dir, "profile.csv", os.str());
  const auto literal = [](const std::string& text) { return jobs::gnuplot_text(text, jobs::GnuplotTextMode::enhanced); };
  // One panel per lattice variable, labelled with what it is ("r[n] = u0[n] - u0[n-1]").
  std::string panels;
  for (std::size_t v = 0; v < variables.size(); ++v)
    panels += fmt::format("set ylabel '{0}'\n"
                          "plot 'profile.csv' skip 1 u 1:{1} w lp pt 3 t '{2}(0)', '' skip 1 u 1:{3} w p pt 4 ps 1.5 t "
                          "'{2}(T_{{b}})', '' skip 1 u 1:{4} w p pt 6 t '{2} seed'\n",
                          v < r.edge.variable_meanings.size() ? literal(r.edge.variable_meanings[v]) : literal(variables[v]),
                          2 + 3 * v, literal(variables[v]), 4 + 3 * v, 3 + 3 * v);
  figures.draw({"profile.gp",
                fmt::format("if (!exists(\"outfile\")) outfile = 'profile.png'\n"
                            "set terminal pngcairo size 1000,{5}\nset output outfile\n"
                            "set datafile separator ','\nset xlabel 'site n'\nset key outside\nset xrange [{6}:{7}]\n"
                            // no marker on the frame; the panels' frames aligned whatever their y labels
                            "set offsets 0, 0, graph 0.05, graph 0.05\nset lmargin 12\n"
                            "set multiplot layout {4},1 title '{0} dark breather ({1} centred), ω_{{b}} = {2:.5f}: Z(0), "
                            "Z(T_{{b}}), seed (model units)'\n{3}unset multiplot\n",
                            literal(c.model->name()), c.center, c.omega_b, panels, variables.size(),
                            150 + 350 * variables.size(), -(N - 1) / 2 - 1, N - 1 - (N - 1) / 2 + 1),
                "profile.png"});
}

// <stem>.csv (re, im, modulus) and <stem>.gp: the multipliers in the complex plane with the unit circle.
void write_multipliers(const std::string& dir, const std::string& stem, const FloquetResult& f, double omega_b,
                       jobs::Figures& figures) {
  std::ostringstream os;
  os << "re,im,modulus\n";
  for (auto l : f.multipliers) os << fmt::format("{:.17g},{:.17g},{:.17g}\n", l.real(), l.imag(), std::abs(l));
  jobs::write_file_atomic(dir, stem + ".csv", os.str());
  // Equal scales on both axes (the unit circle drawn as a circle), a square frame around all multipliers.
  double reach = 1.0;
  for (auto l : f.multipliers) reach = std::max(reach, std::abs(l));
  figures.draw({stem + ".gp",
                fmt::format("if (!exists(\"outfile\")) outfile = '{0}.png'\n"
                            "set terminal pngcairo size 700,700\nset output outfile\n"
                            "set datafile separator ','\nset size ratio -1\nset key off\n"
                            "set xrange [-{2:.6g}:{2:.6g}]\nset yrange [-{2:.6g}:{2:.6g}]\n"
                            "set xlabel 'Re λ'\nset ylabel 'Im λ'\n"
                            "set title 'Floquet multipliers λ, ω_{{b}} = {1:.5f} (grey: unit circle)'\n"
                            "set parametric\nset trange [0:2*pi]\n"
                            "plot cos(t),sin(t) lc 'gray', '{0}.csv' skip 1 using 1:2 with points pt 7 ps 0.8\n",
                            stem, omega_b, 1.08 * reach),
                stem + ".png"});
}

json write(const DarkResult& r, const std::filesystem::path& out) {
  json j = to_json(r);
  const DarkConfig& c = r.config;
  if (!r.newton.converged || (c.step == DarkStep::evolve && r.evolution.periods.empty())) return j;
  const std::string dir = out.string();
  const jobs::OutputLock lock(dir);
  const jobs::OutputListing earlier = jobs::list_output_files(dir);  // before this run writes
  jobs::Figures figures(dir);
  if (c.step == DarkStep::branch) {
    write_branch(r, dir, figures);
    if (c.format == "hdf5" && r.model_file())
      write_model_dark_branch_hdf5(out / "result.h5", model_dark_branch_record(r, j["model"]));
    else if (c.format == "hdf5")
      write_dark_branch_hdf5(out / "result.h5", dark_branch_record(c.params, r.branch, dark_sites(c), c.branch_floquet));
    figures.finish(j);
  } else if (c.step == DarkStep::evolve) {
    if (c.format == "hdf5" && r.model_file())
      write_model_dark_evolution_hdf5(out / "result.h5", model_dark_edge_record(r, j["model"]), dark_evolution_record(r));
    else if (c.format == "hdf5")
      write_dark_evolution_hdf5(out / "result.h5", c.params, dark_evolution_record(r));
    write_evolution(r, dir, figures, j);
  } else {
    write_profile(r, dir, figures);
    if (r.floquet) write_multipliers(dir, "multipliers", *r.floquet, c.omega_b, figures);
    if (c.format == "hdf5" && r.model_file())
      write_model_dark_solution_hdf5(out / "result.h5", model_dark_solution_record(r, j["model"]));
    else if (c.format == "hdf5")
      write_dark_solution_hdf5(out / "result.h5",
                               dark_solution_record(c.params, c.omega_b, r.edge.omega, r.z0, r.seed, r.newton,
                                                    r.measures, r.floquet ? &*r.floquet : nullptr));
    figures.finish(j);
  }
  jobs::record_stale_files(out, earlier, j);
  return j;
}

}  // namespace lrchain::jobs::dark

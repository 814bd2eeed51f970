// write(BrightBreatherResult, out): profile.csv and (floquet) multipliers.csv with their gnuplot
// figures, and summary.json (bright_breather_job.hpp).
#include <sstream>

#include <fmt/format.h>

#include "../dark/dark_steps.hpp"
#include "lrchain/jobs/bright_breather_hdf5.hpp"
#include "lrchain/jobs/bright_breather_job.hpp"
#include "lrchain/jobs/gnuplot_text.hpp"
#include "lrchain/jobs/output_files.hpp"
#include "lrchain/jobs/output_lock.hpp"

namespace lrchain::jobs::bright_breather {

using nlohmann::json;

namespace {

// profile.csv: n, then Z(0) and the NLS seed per variable; profile.gp draws them.
void write_profile(const BrightBreatherResult& r, const std::string& dir, jobs::Figures& figures) {
  const BrightBreatherConfig& c = r.config;
  const Index N = c.sites;
  const std::vector<std::string>& variables = r.edge.variables;
  std::ostringstream os;
  os << "n";
  for (const auto& v : variables) os << "," << v << "_0," << v << "_seed";
  os << "\n";
  for (Index i = 0; i < N; ++i) {
    os << i - (N - 1) / 2;
    for (std::size_t v = 0; v < variables.size(); ++v) {
      const Index at = Index(v) * N + i;
      os << fmt::format(",{:.17g},{:.17g}", r.z0(at), r.seed(at));
    }
    os << "\n";
  }
  jobs::write_file_atomic(dir, "profile.csv", os.str());
  const auto literal = [](const std::string& text) { return jobs::gnuplot_text(text, jobs::GnuplotTextMode::enhanced); };
  std::string plot = "plot ";
  for (std::size_t v = 0; v < variables.size(); ++v)
    plot += fmt::format("{0}'profile.csv' skip 1 u 1:{1} w lp pt 7 t '{2}(0)', '' skip 1 u 1:{3} w p pt 6 ps 1.5 t '{2} NLS seed'",
                        v == 0 ? "" : ", ", 2 + 2 * v, literal(variables[v]), 3 + 2 * v);
  figures.draw({"profile.gp",
                fmt::format("if (!exists(\"outfile\")) outfile = 'profile.png'\n"
                            "set terminal pngcairo size 1000,700\nset output outfile\n"
                            "set datafile separator ','\nset xlabel 'site n'\nset ylabel 'lattice variables: strains or displacements (model units)'\n"
                            "set key outside\nset title '{} bright breather ({} centred), ω_{{b}} = {:.6g}: exact Z(0) and NLS seed'\n{}\n",
                            literal(c.model->name()), c.center, c.omega_b, plot),
                "profile.png"});
}

// branch.csv: one row per branch point (the continued model parameter if not omega_b, omega_b, peak,
// norm_squared, width, stable, max |lambda|).
void write_branch(const BrightBreatherResult& r, const std::string& dir, jobs::Figures& figures) {
  const bool in_parameter = r.config.parameter != "omega_b";
  std::ostringstream os;
  os << (in_parameter ? r.config.parameter + "," : std::string()) << "omega_b,peak,norm_squared,width,stable,max_nontrivial_modulus\n";
  for (std::size_t k = 0; k < r.branch.points.size(); ++k) {
    const auto& profile = r.branch_profiles.at(k);
    if (in_parameter) os << fmt::format("{:.17g},", r.branch.points[k].parameter);
    os << fmt::format("{:.17g},{:.17g},{:.17g},{:.17g}", r.branch.points[k].omega_b, profile.peak,
                      profile.norm_squared, profile.width);
    if (k < r.branch_floquets.size())
      os << fmt::format(",{},{:.17g}\n", r.branch_floquets[k].stable ? 1 : 0, r.branch_floquets[k].max_nontrivial_modulus);
    else
      os << ",,\n";
  }
  jobs::write_file_atomic(dir, "branch.csv", os.str());
  // branch.gp: the norm over the continued parameter, stable points filled, unstable ones open
  const auto literal = [](const std::string& text) { return jobs::gnuplot_text(text, jobs::GnuplotTextMode::enhanced); };
  const int x = 1, norm = in_parameter ? 4 : 3, stable = in_parameter ? 6 : 5;
  figures.draw({"branch.gp",
                fmt::format("if (!exists(\"outfile\")) outfile = 'branch.png'\n"
                            "set terminal pngcairo size 1000,700\nset output outfile\n"
                            "set datafile separator ','\nset xlabel '{0}'\nset ylabel 'norm Σ Z(0)^2'\nset key top left\n"
                            "set title '{1} bright breather ({2} centred): branch in {0}'\n"
                            "plot 'branch.csv' skip 1 u {3}:(strcol({5}) eq '1' ? ${4} : 1/0) w p pt 7 t 'stable', "
                            "'' skip 1 u {3}:(strcol({5}) eq '0' ? ${4} : 1/0) w p pt 6 ps 1.5 t 'unstable', "
                            "'' skip 1 u {3}:{4} w l lc rgb 'gray' t ''\n",
                            literal(r.config.parameter), literal(r.config.model->name()), r.config.center, x, norm,
                            stable),
                "branch.png"});
}

// bifurcations.csv: one row per fold or multiplier crossing (branch_bifurcations.hpp), located in
// the continued parameter (omega_b, or the model parameter: its name heads the columns).
void write_bifurcations(const BrightBreatherResult& r, const std::string& dir) {
  std::ostringstream os;
  const std::string& p = r.config.parameter;
  os << (p == "omega_b" ? std::string("kind,index,omega_b,norm_squared,omega_low,omega_high")
                        : fmt::format("kind,index,{0},norm_squared,{0}_low,{0}_high", p))
     << ",location_error,multiplier_re,multiplier_im\n";  // empty: not located
  for (const auto& b : r.bifurcations) {
    os << fmt::format("{},{},{:.17g},{:.17g},{:.17g},{:.17g},", b.kind, b.index, b.omega_b, b.norm_squared,
                      b.omega_low, b.omega_high);
    os << (b.located ? fmt::format("{:.17g}", b.location_error) : std::string()) << ','
       << (b.multiplier ? fmt::format("{:.17g},{:.17g}", b.multiplier->real(), b.multiplier->imag()) : std::string(","))
       << '\n';
  }
  jobs::write_file_atomic(dir, "bifurcations.csv", os.str());
}

// evolution.csv: per period m the time, the deviation from the breather (absolute and relative to
// its peak) and the energy; evolution.gp draws ln(deviation) and the predicted growth from the start.
void write_evolution(const BrightBreatherResult& r, const std::string& dir, jobs::Figures& figures) {
  const sim::bright::BrightEvolution& e = *r.evolution;
  const double peak = r.z0.cwiseAbs().maxCoeff();
  std::ostringstream os;
  os << "period,t,deviation,relative_deviation,energy\n";
  for (std::size_t m = 0; m < e.samples.size(); ++m)
    os << fmt::format("{},{:.17g},{:.17g},{:.17g},{:.17g}\n", m, e.samples[m].t, e.samples[m].deviation,
                      e.samples[m].deviation / peak, e.samples[m].energy);
  jobs::write_file_atomic(dir, "evolution.csv", os.str());
  const auto literal = [](const std::string& text) { return jobs::gnuplot_text(text, jobs::GnuplotTextMode::enhanced); };
  figures.draw({"evolution.gp",
                fmt::format("if (!exists(\"outfile\")) outfile = 'evolution.png'\n"
                            "set terminal pngcairo size 1000,700\nset output outfile\n"
                            "set datafile separator ','\nset xlabel 't'\nset ylabel 'max |[Z, Ż](t) - [Z(0), 0]|'\n"
                            "set logscale y\nset key top left\n"
                            "set title '{} bright breather ({} centred), ω_{{b}} = {:.6g}: deviation at multiples of T_{{b}}'\n"
                            "plot 'evolution.csv' skip 1 u 2:3 w lp pt 7 t 'measured', "
                            "{:.17g}*exp({:.17g}*x) w l dt 2 t 'Floquet: ln|λ_{{max}}|/T_{{b}} = {:.4g}'\n",
                            literal(r.config.model->name()), r.config.center, r.config.omega_b,
                            e.samples.front().deviation > 0 ? e.samples.front().deviation : 1e-300,
                            r.predicted_growth_rate, r.predicted_growth_rate),
                "evolution.png"});
}

}  // namespace

json write(const BrightBreatherResult& r, const std::filesystem::path& out) {
  json j = to_json(r);
  if (failure(r)) return j;
  const std::string dir = out.string();
  const OutputLock lock(dir);
  const jobs::OutputListing earlier = jobs::list_output_files(dir);  // before this run writes
  jobs::Figures figures(dir);
  write_profile(r, dir, figures);
  if (r.config.step == BrightStep::branch) {
    write_branch(r, dir, figures);
    write_bifurcations(r, dir);
  }
  if (r.evolution) write_evolution(r, dir, figures);
  if (r.floquet) dark::write_multipliers(dir, "multipliers", r.floquet->multipliers, r.config.omega_b, figures);
  if (r.config.format == "hdf5") write_bright_breather_hdf5(out / "result.h5", bright_breather_record(r));
  figures.finish(j);
  jobs::write_file_atomic(dir, "summary.json", j.dump(2) + "\n");
  jobs::record_stale_files(out, earlier, j);
  return j;
}

}  // namespace lrchain::jobs::bright_breather

// JSON summary, data files and gnuplot figures of a model bright-breather run (bright_run.hpp).
#include <fmt/format.h>

#include <nlohmann/json.hpp>

#include "lrchain/provenance_json.hpp"
#include "lrchain/jobs/simulate/model_bright_outputs.hpp"
#include "lrchain/jobs/output_files.hpp"
#include "lrchain/sim/strain_sites.hpp"

namespace lrchain::jobs {

using namespace lrchain::sim;

std::vector<std::string> model_bright_warnings(const ModelBrightResult& r) {
  std::vector<std::string> warnings;
  if (!r.end_reached_at) return warnings;
  const double most = 100 * r.max_end_energy_fraction.value_or(0.0);
  if (*r.end_reached_at == 0)
    warnings.push_back(fmt::format("the lattice is too short for the breather (width 1/a = {:.3g} sites): {:.1f} % of "
                                   "its energy is within {} sites of a fixed end (at most, over the run; above 1 % from the start); give more --sites",
                                   1 / r.inverse_width, most, r.end_zone));
  else
    warnings.push_back(fmt::format("the breather reached a fixed end at t = {:.6g}: more than {:g} % of the energy "
                                   "within {} sites of an end (at most {:.1f} %), so the run is no longer that of a "
                                   "breather on an unbounded lattice; give more --sites, fewer --periods or "
                                   "--ansatz-ends",
                                   *r.end_reached_at, 100 * sim::end_energy_limit, r.end_zone, most));
  return warnings;
}

nlohmann::json to_json(const Model& model, const ModelBrightConfig& c, const ModelBrightResult& r) {
  nlohmann::json j;
  j["experiment"] = "bright";
  j["provenance"] = provenance_json();
  j["branch"] = model.definition().branch_names.at(c.branch);
  j["theta"] = c.theta;
  j["sites"] = strain_site_count(c.N);  // n = -N..N, as --sites takes it
  j["periods"] = c.periods;
  j["form"] = r.mean_flow ? "strain" : "displacement";
  j["ansatz_ends"] = r.ansatz_ends;
  j["integrator"] = r.ansatz_ends ? nlohmann::json{{"stepper", "rkf78"}, {"abs_tol", r.tolerance}, {"rel_tol", r.tolerance}}
                                  : nlohmann::json{{"stepper", "srkn11b"}, {"dt", r.dt}};
  j["ansatz"] = {{"omega", r.omega},         {"omega_b", r.omega_b},     {"T_b", r.period},
                 {"group_velocity", r.group_velocity}, {"curvature", r.curvature}, {"h_tilde", r.h_tilde},
                 {"lambda", r.mean_flow ? nlohmann::json(r.lambda) : nlohmann::json(nullptr)},
                 {"M1", r.M1},               {"M2", r.M2},               {"inverse_width", r.inverse_width}};
  // Which terms the ansatz holds, and the second-order ones per field (per unit A^2, |A|^2).
  nlohmann::json terms = {"kernel vector"};
  if (r.mean_flow) terms.push_back("mean flow (lambda)");
  if (r.uses_second_order) terms.insert(terms.end(), {"second harmonic", "mean offset", "kernel gradient"});
  j["ansatz"]["terms"] = terms;
  nlohmann::json kernel = nlohmann::json::array(), harmonic = nlohmann::json::array();
  for (const auto& k : r.kernel) kernel.push_back({k.real(), k.imag()});
  nlohmann::json gradient = nlohmann::json::array();
  for (const auto& w : r.second_order.second_harmonic) harmonic.push_back({w.real(), w.imag()});
  for (const auto& g : r.second_order.kernel_gradient) gradient.push_back({g.real(), g.imag()});
  j["ansatz"]["kernel"] = kernel;
  j["ansatz"]["second_harmonic"] = r.uses_second_order ? harmonic : nlohmann::json(nullptr);
  j["ansatz"]["mean_offset"] = r.uses_second_order ? nlohmann::json(r.second_order.mean) : nlohmann::json(nullptr);
  j["ansatz"]["kernel_gradient"] = r.uses_second_order ? gradient : nlohmann::json(nullptr);
  j["compared"] = r.mean_flow ? "strains u_f[n] - u_f[n-1]" : "displacements u_f[n]";
  j["max_E"] = r.max_error;
  j["final_E"] = r.final_error;
  j["max_E_x"] = r.max_error.at(0);
  j["energy0"] = r.energy0;
  // Driven (ansatz) ends exchange energy with the outside: no conservation to report.
  j["max_relative_energy_drift"] = r.ansatz_ends ? nlohmann::json(nullptr) : nlohmann::json(r.max_energy_drift);
  j["centre_speed"] = r.centre_speed ? nlohmann::json(*r.centre_speed) : nlohmann::json(nullptr);
  j["centre_speed_vs_c"] =
      r.centre_speed && r.group_velocity != 0 ? nlohmann::json(*r.centre_speed / r.group_velocity) : nlohmann::json(nullptr);
  j["max_end_energy_fraction"] =
      r.max_end_energy_fraction ? nlohmann::json(*r.max_end_energy_fraction) : nlohmann::json(nullptr);
  j["end_reached_at"] = r.end_reached_at ? nlohmann::json(*r.end_reached_at) : nlohmann::json(nullptr);
  j["warnings"] = model_bright_warnings(r);
  j["t_end"] = r.stats.t_reached;
  j["steps"] = r.stats.steps;
  j["rhs_evaluations"] = r.stats.rhs_evaluations;
  j["solve_seconds"] = r.solve_seconds;
  return j;
}

namespace {

// errors.png: E_f(t) per field, then one panel per field with its final profile: the lattice (a
// line through every site) and the ansatz (a marker at every site: a carrier of a few sites'
// period sampled at every second site shows its markers off the crests), over the sites where the
// first field exceeds 1 % of its peak.
std::string errors_script(const ModelBrightResult& r) {
  const std::size_t fields = r.max_error.size();
  std::string plots, profiles;
  for (std::size_t f = 0; f < fields; ++f) {
    plots += fmt::format("{}'series.csv' using 1:{} skip 1 with lines lw 1.5 title \"E_{}\"", f ? ", \\\n     " : "", f + 2, f);
    profiles += fmt::format(
        "set ylabel \"x_{0} = {1}\"\n"
        "plot 'snapshot_final.csv' using 1:{2} skip 1 with lines lw 1.5 title \"lattice\", \\\n"
        "     'snapshot_final.csv' using 1:{3} skip 1 with points pt 6 ps 0.7 lc rgb \"black\" title \"ansatz\"\n",
        f, r.mean_flow ? fmt::format("u_{0}[n] − u_{0}[n−1] (strain, model units)", f) : fmt::format("u_{}[n] (displacement, model units)", f),
        2 * f + 2, 2 * f + 3);
  }
  return fmt::format(R"GP(# Relative error of the lattice against the NLS bright-breather ansatz per field, and the final profiles.
if (!exists("outfile")) outfile = 'errors.png'
set terminal pngcairo size 1200,{} font ",11"
set output outfile
set datafile separator ","
set multiplot layout {},1
set xlabel "t (model units)"
set ylabel "relative error E_f of the lattice\nagainst the ansatz"
set offsets 0, 0, graph 0.08, 0
plot {}
# The profiles where the breather is: the sites where |x_0| exceeds 1 % of its largest value.
stats 'snapshot_final.csv' using 2 skip 1 nooutput name "X"
peak = abs(X_max) > abs(X_min) ? abs(X_max) : abs(X_min)
stats 'snapshot_final.csv' using ((abs($2) > 0.01*peak) ? $1 : NaN) skip 1 nooutput name "N"
# five sites beyond them, and half a site more so that no marker lies on the frame
set xrange [N_min - 5.5 : N_max + 5.5]
set xlabel "site n (profile at the end of the run)"
set key top right opaque box
set offsets 0, 0, graph 0.05, graph 0.05
{}unset multiplot
)GP",
                     350 * (fields + 1), fields + 1, plots, profiles);
}

}  // namespace

std::vector<std::string> write_model_bright_outputs(const std::filesystem::path& dir, const ModelBrightResult& r,
                                                    const nlohmann::json& summary, bool draw_figures) {
  return write_run_outputs(dir, r.record, summary.dump(2), {{"errors.gp", errors_script(r), "errors.png"}}, draw_figures);
}

}  // namespace lrchain::jobs

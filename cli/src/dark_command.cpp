// `lrchain dark solve|continue|floquet|evolve`: exact stationary dark breathers (Sec. 5.3-5.4,
// Figs. 17-25): shooting Newton from the eq:xy_app seed, pseudo-arclength continuation in omega_b,
// Floquet multipliers, space-time evolution by direct integration. JSON on stdout, Newton progress
// on stderr, files in --out.
#include <CLI/CLI.hpp>
#include <cmath>
#include <filesystem>
#include <cstdio>
#include <fmt/format.h>
#include <nlohmann/json.hpp>
#include <numbers>
#include <optional>
#include <sstream>
#include <stdexcept>

#include "commands.hpp"
#include "lrchain/sim/dark/dark_hdf5.hpp"
#include "figure_format_option.hpp"
#include "figure_text.hpp"
#include "help_text.hpp"
#include "lrchain/provenance_json.hpp"
#include "lrchain/ansatz/dark_breather.hpp"
#include "lrchain/checked_number.hpp"
#include "lrchain/config/option_caps.hpp"
#include "lrchain/errors.hpp"
#include "lrchain/regime/frequency_band.hpp"
#include "lrchain/sim/dark/continuation.hpp"
#include "lrchain/sim/dark/evolution.hpp"
#include "lrchain/sim/output_files.hpp"
#include "lrchain/sim/resource_estimate.hpp"
#include "lrchain/sim/output_lock.hpp"
#include "lrchain/sim/dark/model_dark_ansatz.hpp"
#include "lrchain/sim/dark/model_shooting.hpp"
#include "lrchain/sim/model_lattice_bloch.hpp"
#include "model_option.hpp"
#include "options.hpp"
#include "stop_signals.hpp"

namespace lrchain::cli {

namespace {
using namespace lrchain::sim::dark;
using nlohmann::json;

struct DarkArgs {
  Params p;
  double omega_b = 0;
  std::string branch = "optical", center = "bond", mode = "reversible";
  bool branch_given = false;  // --branch on the command line (a model's default: its defocusing edge)
  ModelSelection model;       // --model FILE --set NAME=VALUE (empty: the resonant chain through Params)
  Index sites = 101;
  bool json_out = false, quiet = false, full_monodromy = false;
  std::string out;
  Index points = 100;
  double ds = 0.1, omega_min = 0, omega_max = 0;
  double t_end = 0;
  Index samples = 24;
  double max_memory = 0;  // bytes (--max-memory); 0: the machine's available memory
  std::string format = "csv";  // --format hdf5: also OUT/result.h5 (solve, floquet, continue)
};

enum class DarkJob { solve, floquet, branch, evolve };

// One line per Newton iteration on stderr.
void print_newton_progress(const NewtonRecord& r) {
  fmt::print(stderr, "newton {:2d}  max|F| = {:.3e}  max|step| = {:.3e}\n", r.iteration, r.residual, r.step);
}

// Checks every option of a dark job, its memory and output size, and --out, before any Newton
// iteration and before anything is written (InvalidParameter/InputError: exit 2).
void validate_job(const DarkArgs& a, DarkJob job) {
  validate(a.p);
  make_dark_breather_ansatz(a.p, parse_branch(a.branch), a.omega_b);  // checks --omega-b and --branch
  parse_dark_center(a.center);
  if (a.sites < 9 || a.sites % 2 == 0)
    throw InvalidParameter("sites", "must be an odd integer >= 9 (a staggered dark breather fits "
                                    "periodic ends only on an odd number of sites)");
  const double period = 2 * std::numbers::pi / a.omega_b;
  const double shooting_time =
      a.mode == "full" || job == DarkJob::floquet ? period : (a.center == "site" ? period / 2 : period / 4);
  double periods = 0;
  if (job == DarkJob::branch) {
    // The continuation adapts its step between 1e-5 and 1; it starts at omega_b, which must lie
    // inside the window [omega-min, omega-max] it stops outside of.
    checked_finite(a.omega_max, "omega-max");
    if (a.omega_max != 0 && !(a.omega_max > 0))
      throw InvalidParameter("omega-max", "must be 0 (the band edge) or a frequency above omega-b");
    validate_continuation_window(a.p, a.omega_b, a.ds, a.omega_min,
                                 a.omega_max > 0 ? std::optional<double>(a.omega_max) : std::nullopt);
  }
  if (job == DarkJob::evolve) {
    if (!(std::isfinite(a.t_end) && a.t_end >= period))
      throw InvalidParameter("t-end", fmt::format("must be a finite time >= one period T_b = 2 pi/omega_b = {:.6g} "
                                                  "(dimensionless time of Sec. 2)", period));
    periods = double(config::checked_option_count(a.t_end, period, config::dark_periods, "t-end"));
  }
  const sim::ResourceEstimate e =
      sim::estimate_dark_breather(a.sites, job == DarkJob::floquet || job == DarkJob::branch, shooting_time, periods);
  if (e.dominant == "period")
    sim::check_memory(e, a.max_memory, "omega-b", "raise omega-b (a shorter period T_b)");
  else if (e.dominant == "periods")
    sim::check_memory(e, a.max_memory, "t-end", "lower t-end");
  else
    sim::check_memory(e, a.max_memory, "sites", "lower sites");
  if (!a.out.empty()) {
    std::error_code ec;
    if (std::filesystem::exists(a.out, ec) && !std::filesystem::is_directory(a.out, ec))
      throw InputError("--out '" + a.out + "' exists and is not a directory");
    sim::check_output_space(e, a.out, "out", "choose another --out");
  }
}

void add_common(CLI::App& sub, DarkArgs& a) {
  add_model_options(sub, a.p, false);
  add_number(sub, "--omega-b", a.omega_b, "breather frequency omega_b (dimensionless, time unit of Sec. 2; period T_b = 2 pi/omega_b), on the side of the theta = pi band edge where (omega_b - omega) h_tilde > 0: below it for the resonant chain (required)")->required();
  sub.add_option_function<std::string>(
         "--branch", [&a](const std::string& name) { a.branch = name, a.branch_given = true; },
         "branch whose theta = pi band edge the breather bifurcates from: optical|acoustic (default optical); with "
         "--model a branch of the model (default: the first whose theta = pi edge is defocusing)")
      ->type_name("NAME");
  add_model_file_options(sub, a.model);
  sub.get_option("--set")->description("model parameter, repeatable: --set w0=2 --set b=-1/2 (default: the model "
                                       "file's defaults; with --model only)");
  sub.add_option("--center", a.center, "family: bond (n0 = 1/2) | site (n0 = 0) (default bond)")
      ->check(CLI::IsMember({"bond", "site"}).description(""))
      ->type_name("bond|site");
  add_integer(sub, "--sites", a.sites, config::dark_sites.least, config::dark_sites.most,
              "odd number of lattice sites per field x, y (periodic ends; default 101)");
  sub.add_option("--mode", a.mode, "shooting: reversible (half/quarter period) | full (whole period, a check) (default reversible)")
      ->check(CLI::IsMember({"reversible", "full"}).description(""))
      ->type_name("reversible|full");
  sub.add_flag("--json", a.json_out, "print the JSON summary on one line (default: indented)");
  sub.add_flag("--quiet", a.quiet, "no Newton progress on stderr (default: progress shown)");
  sub.add_option("--out", a.out, "output directory for CSV data and gnuplot figures (default: none, only the JSON on stdout)")
      ->type_name("DIR");
  add_max_memory(sub, a.max_memory);
  add_figure_format(sub);
}

json floquet_json(const FloquetResult& f, bool with_multipliers) {
  json j = {{"kind", f.kind()},
            {"max_modulus", f.max_modulus},
            {"max_real", f.max_real},
            {"max_period_doubling", f.max_period_doubling},
            {"max_oscillatory", f.max_oscillatory},
            {"near_one", f.near_one},
            {"pairing_defect", f.pairing_defect},
            {"log_det", f.log_det}};
  if (with_multipliers) {
    json m = json::array();
    for (auto l : f.multipliers) m.push_back({l.real(), l.imag()});
    j["multipliers"] = m;
  }
  return j;
}

json measures_json(const DarkMeasures& m) {
  return {{"norm_squared", m.norm_squared}, {"K_x", m.K_x}, {"K_y", m.K_y}, {"C_x", m.C_x},
          {"C_y", m.C_y}, {"E_b", m.E_b}, {"max_strain", m.max_strain}};
}

// Seeds from eq:xy_app and runs Newton; on failure prints the JSON summary (converged false, the
// residual history, the failure) and throws NumericalFailure (exit 3).
struct Solved {
  DarkShooting shooting;
  DarkBreatherAnsatz ansatz;
  NewtonResult newton;
};
json base_json(const DarkArgs& a, const DarkBreatherAnsatz& ansatz, const NewtonResult& newton);
Solved solve(const DarkArgs& a) {
  validate(a.p);
  const Branch edge = parse_branch(a.branch);
  const DarkCenter center = parse_dark_center(a.center);
  const DarkBreatherAnsatz ansatz = make_dark_breather_ansatz(a.p, edge, a.omega_b);
  DarkShooting shooting(a.p, a.sites, center, parse_shooting_mode(a.mode));
  NewtonOptions o;
  if (!a.quiet)
    o.progress = print_newton_progress;
  NewtonResult res = newton_solve(shooting, shooting.unknowns_from_z(dark_seed(ansatz, center, a.sites)),
                                  a.omega_b, o);
  if (!res.converged) {
    const std::string message = newton_failure_message(res, a.omega_b);
    json j = base_json(a, ansatz, res);
    j["failure"] = {{"kind", "newton"}, {"message", message}};
    std::printf("%s\n", j.dump(a.json_out ? -1 : 2).c_str());
    throw NumericalFailure(message);
  }
  return {std::move(shooting), ansatz, std::move(res)};
}

// The model, the options, the band edge and the Newton history of a dark job; "failure" null unless set.
json base_json(const DarkArgs& a, const DarkBreatherAnsatz& ansatz, const NewtonResult& newton) {
  json hist = json::array();
  for (const auto& r : newton.history) hist.push_back(r.residual);
  return {{"model", model_json(resonant_chain_model(a.p))},
          {"branch", a.branch}, {"center", a.center}, {"sites", a.sites}, {"mode", a.mode},
          {"omega_b", a.omega_b}, {"omega_edge", ansatz.omega},
          {"newton_converged", newton.converged}, {"newton_residuals", hist}, {"failure", nullptr},
          {"provenance", provenance_json()}};
}
json base_json(const DarkArgs& a, const Solved& s) { return base_json(a, s.ansatz, s.newton); }

void write_profile(const std::string& dir, const std::string& name, const Eigen::VectorXd& z0,
                   const Eigen::VectorXd& seed, const Eigen::VectorXd& zT) {
  const Index N = z0.size() / 2;
  std::ostringstream os;
  os << "n,x0,y0,x_seed,y_seed,x_T,y_T\n";
  for (Index i = 0; i < N; ++i)
    os << fmt::format("{},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g}\n", i - (N - 1) / 2, z0(i),
                      z0(N + i), seed(i), seed(N + i), zT(i), zT(N + i));
  sim::write_file_atomic(dir, name, os.str());
}

void write_multipliers(const std::string& dir, const std::string& stem, const FloquetResult& f,
                       double omega_b, sim::Figures& figures) {
  std::ostringstream os;
  os << "re,im,modulus\n";
  for (auto l : f.multipliers) os << fmt::format("{:.17g},{:.17g},{:.17g}\n", l.real(), l.imag(), std::abs(l));
  sim::write_file_atomic(dir, stem + ".csv", os.str());
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

void run_solve(const DarkArgs& a, bool floquet) {
  validate_job(a, floquet ? DarkJob::floquet : DarkJob::solve);
  Solved s = solve(a);
  json j = base_json(a, s);
  const Eigen::VectorXd z0 = s.shooting.z_from_unknowns(s.newton.q);
  const DarkMeasures m = measure_dark_breather(a.p, z0, a.omega_b, s.shooting.integration());
  j["measures"] = measures_json(m);
  FloquetResult f;
  if (floquet) {
    Eigen::VectorXd r;
    Eigen::MatrixXd J, A;
    s.shooting.evaluate(s.newton.q, a.omega_b, r, &J, &A);
    if (a.full_monodromy || s.shooting.mode() == ShootingMode::full) {
      DarkShooting full(a.p, a.sites, s.shooting.center(), ShootingMode::full);
      full.evaluate(full.unknowns_from_z(z0), a.omega_b, r, &J, &A);
      f = floquet_from_monodromy(A);
      j["monodromy"] = "full period";
    } else {
      f = floquet_reversible(s.shooting, A);
      j["monodromy"] = "reversible reduction";
    }
    j["floquet"] = floquet_json(f, true);
  }
  if (!a.out.empty()) {
    const sim::OutputLock lock(a.out);
    sim::Figures figures(a.out);
    const auto seed = dark_seed(s.ansatz, s.shooting.center(), a.sites);
    auto evo = dark_breather_evolution(a.p, z0, 2 * std::numbers::pi / a.omega_b, 1, s.shooting.integration());
    write_profile(a.out, "profile.csv", z0, seed, evo.back());
    figures.draw({"profile.gp",
                        fmt::format("if (!exists(\"outfile\")) outfile = 'profile.png'\n"
                                    "set terminal pngcairo size 1000,700\nset output outfile\n"
                                    "set datafile separator ','\nset xlabel 'site n'\n"
                                    "set ylabel 'strains x_{{n}}, y_{{n}} (dimensionless)'\nset key outside\n"
                                    "set title 'dark breather ({} centred), ω_{{b}} = {:.5f}: Z(0), Z(T_{{b}}), seed eq. (48)'\n"
                                    "plot 'profile.csv' skip 1 u 1:2 w lp pt 3 t 'x_{{n}}(0)', '' skip 1 u 1:6 w p pt 4 ps 1.5 t 'x_{{n}}(T_{{b}})', "
                                    "'' skip 1 u 1:4 w p pt 6 t 'x seed', '' skip 1 u 1:3 w lp pt 3 t 'y_{{n}}(0)', "
                                    "'' skip 1 u 1:7 w p pt 4 ps 1.5 t 'y_{{n}}(T_{{b}})', '' skip 1 u 1:5 w p pt 6 t 'y seed'\n",
                                    a.center, a.omega_b),
                        "profile.png"});
    if (floquet) write_multipliers(a.out, "multipliers", f, a.omega_b, figures);
    if (a.format == "hdf5")
      sim::dark::write_dark_solution_hdf5(std::filesystem::path(a.out) / "result.h5",
                                          sim::dark::dark_solution_record(a.p, a.omega_b, s.ansatz.omega, z0, seed, s.newton, m, floquet ? &f : nullptr));
    figures.finish(j);
  }
  std::printf("%s\n", j.dump(a.json_out ? -1 : 2).c_str());
}

// A count, or null where there is none (a smooth model's contact changes).
json count_json(const std::optional<Index>& count) { return count ? json(*count) : json(nullptr); }

// Continues a solved breather q0 away from the band edge omega_edge (Params or model shooting),
// prints the JSON summary j completed with the branch and writes --out. `label` names the lattice
// in figure titles. A model job (`model_points`) also lists every point's omega_b, E_b and contact
// changes per period in the JSON (`branch_points`) and the contact changes in branch.csv.
void continue_and_report(const DarkArgs& a, const DarkShootingProblem& shooting, const Eigen::VectorXd& q0,
                         double omega_edge, json j, const std::string& label, bool model_points = false) {
  StopSignals signals;  // SIGINT/SIGTERM: stop after the current branch point, write the branch so far
  ContinuationOptions o;
  o.stop = StopSignals::flag();
  o.max_points = a.points;
  o.ds = a.ds;
  o.omega_min = a.omega_min;
  const bool above = a.omega_b > omega_edge;  // a model edge with h_tilde > 0: the branch rises from it
  o.direction = above ? 1.0 : -1.0;
  o.omega_min = above ? std::max(a.omega_min, omega_edge) : a.omega_min;
  o.omega_max = a.omega_max > 0 ? a.omega_max : above ? 1e300 : omega_edge;
  std::ostringstream csv;
  csv << "omega_b,norm_squared,K_x,K_y,C_x,C_y,E_b,stability,max_modulus,max_real,max_period_doubling,"
         "max_oscillatory,iterations" << (model_points ? ",contact_changes_per_period" : "") << "\n";
  std::ostringstream mult;  // omega_b, |lambda|, type (0 complex, 1 real>0, 2 real<0)
  mult << "omega_b,modulus,type,branch_part\n";
  int part = 0, count = 0;
  bool unstable_in[2] = {false, false};  // a modulus > 1 before / after the first turning point
  double last_tangent = -1;
  auto on_point = [&](const BranchPoint& b) {
    if (!a.quiet)
      std::fprintf(stderr, "point %3d omega_b = %.6f norm^2 = %.5f %s max|lambda| = %.5f%s\n", count++, b.omega_b,
                   b.measures.norm_squared, b.floquet.kind().c_str(), b.floquet.max_modulus,
                   b.contact_changes_per_period
                       ? fmt::format(" contact changes {}", *b.contact_changes_per_period).c_str()
                       : "");
    if ((b.tangent_omega > 0) != (last_tangent > 0)) ++part;
    last_tangent = b.tangent_omega;
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
      mult << fmt::format("{:.12g},{:.12g},{},{}\n", b.omega_b, std::abs(l), real ? (l.real() > 0 ? 1 : 2) : 0, part);
      unstable_in[part >= 1] = true;
    }
  };
  const BranchResult br = continue_branch(shooting, q0, a.omega_b, o, on_point);
  j["points"] = br.points.size();
  j["stop_reason"] = br.stop_reason;
  j["turning_points"] = br.turning_points;
  j["interrupted"] = br.interrupted;
  double worst = 0;
  for (const auto& b : br.points) worst = std::max(worst, b.measures.E_b);
  j["max_E_b"] = worst;
  if (model_points) {
    json points = json::array();
    for (const auto& b : br.points)
      points.push_back({{"omega_b", b.omega_b}, {"E_b", b.measures.E_b},
                        {"contact_changes_per_period", count_json(b.contact_changes_per_period)}});
    j["branch_points"] = points;
    j["contact_changes_per_period"] = points.empty() ? json(nullptr) : points.front()["contact_changes_per_period"];
  }
  const bool failed = br.points.size() < 2 && !br.interrupted;  // the corrector failed at once
  if (failed) j["failure"] = {{"kind", "continuation"}, {"message", "continuation stopped: " + br.stop_reason}};
  if (!a.out.empty()) {
    const sim::OutputLock lock(a.out);
    sim::Figures figures(a.out);
    sim::write_file_atomic(a.out, "branch.csv", csv.str());
    sim::write_file_atomic(a.out, "floquet_moduli.csv", mult.str());
    if (a.format == "hdf5")
      sim::dark::write_dark_branch_hdf5(std::filesystem::path(a.out) / "result.h5", sim::dark::dark_branch_record(a.p, br, a.sites, o.floquet));
    // The x range reaches the band edge, so that its line (omega_opt or omega_acs) is inside the frame.
    double lowest = omega_edge;
    for (const auto& b : br.points) lowest = std::min(lowest, b.omega_b);
    const double margin = 0.03 * std::max(omega_edge - lowest, 1e-3);
    figures.draw({"branch.gp",
                        fmt::format("if (!exists(\"outfile\")) outfile = 'branch.png'\n"
                                    "set terminal pngcairo size 900,650\nset output outfile\n"
                                    "set datafile separator ','\nset xlabel 'breather frequency ω_{{b}}'\n"
                                    "set ylabel 'renormalised ℓ^{{2}} norm squared, eq. (51)'\n"
                                    "set xrange [{4:.8g}:{5:.8g}]\nset key top left\n"
                                    "set arrow from {0},graph 0 to {0},graph 1 nohead lc 'black'\n"
                                    "set label 'band edge {0:.4f}' at {0},graph 0.96 right offset -0.5,0\n"
                                    "set title '{1} {2}-centred dark breathers, {3} (red: real instability)'\n"
                                    "plot 'branch.csv' skip 1 u 1:2 w l lc 'blue' t 'branch', "
                                    "'' skip 1 u 1:(strstrt(strcol(8),'real') > 0 ? $2 : 1/0) w p pt 7 lc 'red' t 'real instability'\n",
                                    omega_edge, a.branch, a.center, gnuplot_literal(label), lowest - margin,
                                    omega_edge + margin),
                        "branch.png"});
    // One panel per part of the branch that was computed (before / after the first turning point);
    // a part without multipliers off the unit circle says so instead of showing an empty frame.
    const bool turned = part >= 1;
    std::string moduli = fmt::format(
        "if (!exists(\"outfile\")) outfile = 'floquet_moduli.png'\n"
        "set terminal pngcairo size 1000,{3}\nset output outfile\n"
        "set datafile separator ','\nset xlabel 'breather frequency ω_{{b}}'\nset ylabel 'Floquet modulus |λ|'\n"
        "set offsets 0, 0, graph 0.1, 0\nset key off\n"
        "set multiplot layout {4},1 title '{0} {1}-centred, {2}: Floquet moduli |λ| > 1 (blue: complex, red: real > 0, green: real < 0)'\n",
        a.branch, a.center, gnuplot_literal(label), turned ? 700 : 400, turned ? 2 : 1);
    for (int p = 0; p < (turned ? 2 : 1); ++p) {
      const std::string select = p == 0 ? "$4==0" : "$4>=1";
      moduli += fmt::format("set title '{}'\n", p == 0 ? "weakly nonlinear (before the turning point)"
                                                       : "strongly nonlinear (after the turning point)");
      if (!unstable_in[p]) {
        moduli += "set yrange [0.9:1.1]\nset label 1 'all multipliers on the unit circle: linearly stable' at graph 0.5, graph 0.7 center\n"
                  "plot 'branch.csv' skip 1 u 1:(1) w l lc 'grey' dt 2\nunset label 1\nset autoscale y\n";
        continue;
      }
      moduli += fmt::format("plot 'floquet_moduli.csv' skip 1 u 1:({0} && $3==0 ? $2 : 1/0) w p pt 7 ps 0.5 lc 'blue', "
                            "'' skip 1 u 1:({0} && $3==1 ? $2 : 1/0) w p pt 13 lc 'red', "
                            "'' skip 1 u 1:({0} && $3==2 ? $2 : 1/0) w p pt 5 lc 'dark-green'\n", select);
    }
    moduli += "unset multiplot\n";
    figures.draw({"floquet_moduli.gp", moduli, "floquet_moduli.png"});
    figures.finish(j);
  }
  std::printf("%s\n", j.dump(a.json_out ? -1 : 2).c_str());
  std::fflush(stdout);
  if (br.interrupted)
    throw Interrupted(StopSignals::received(),
                      fmt::format("interrupted by {} after {} branch points{}",
                                  StopSignals::name(StopSignals::received()), br.points.size(),
                                  a.out.empty() ? std::string() : "; the branch so far is in " + a.out));
  if (failed) throw NumericalFailure("continuation stopped: " + br.stop_reason);
}

void run_continue(const DarkArgs& a) {
  validate_job(a, DarkJob::branch);
  Solved s = solve(a);
  continue_and_report(a, s.shooting, s.newton.q, s.ansatz.omega, base_json(a, s), fmt::format("ρ = {:.4g}", a.p.rho));
}

// One lattice variable of an evolution's files: its name (x, r, u0, ...) and axis label.
struct EvolutionVariable {
  std::string name, label;
};

// Space-time files and figures of a direct integration (Figs. 21, 22, 25) for any lattice variables:
// <name>_spacetime.bin per variable, evolution.csv, snapshots.csv (n, every v_0, every v_T),
// evolution.gp (snapshots and space-time maps) and diagnostics.gp (E_b(t), position), summary.json.
void write_evolution(const std::string& dir, const DarkEvolution& e, const std::vector<EvolutionVariable>& variables,
                     const std::string& title, json& summary) {
  const Index N = e.sites;
  const Index V = Index(variables.size());
  const sim::OutputLock lock(dir);
  sim::Figures figures(dir);
  for (Index field = 0; field < V; ++field) {
    sim::SpaceTime st;
    st.quantity = variables[std::size_t(field)].name + "_n";
    st.first_label = -(N - 1) / 2;
    st.sites = N;
    for (std::size_t m = 0; m < e.snapshots.size(); ++m) {
      st.times.push_back(static_cast<double>(m) * e.period);
      for (Index i = 0; i < N; ++i) st.values.push_back(static_cast<float>(e.snapshots[m](field * N + i)));
    }
    sim::write_spacetime_binary(dir, variables[std::size_t(field)].name + "_spacetime.bin", st);
  }
  std::ostringstream ev;
  ev << "t,E_b,C_x,K_x,position,depth\n";
  for (const auto& r : e.periods)
    ev << fmt::format("{:.12g},{:.6e},{:.9g},{:.9g},{:.6f},{:.6g}\n", r.t, r.E_b, r.C_x, r.K_x, r.position, r.depth);
  sim::write_file_atomic(dir, "evolution.csv", ev.str());
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
  sim::write_file_atomic(dir, "snapshots.csv", sn.str());
  const double T = e.periods.back().t;
  const double nmin = double(-(N - 1) / 2) - 0.5, nmax = double((N - 1) / 2) + 0.5;
  const double height = 0.94 / double(V);
  std::string maps, snapshots, right;
  for (Index k = 0; k < V; ++k) {
    const EvolutionVariable& v = variables[std::size_t(k)];
    const double origin = double(V - 1 - k) * height;
    const std::string name = gnuplot_literal(v.name);  // v.label is enhanced text ("strain x_{n}")
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
                  "set key outside top center horizontal\nset xrange [{2}:{3}]\nset xlabel 'site n'\n"
                  "{7}"
                  "set datafile separator whitespace\n"
                  "set ylabel 't (dimensionless)'\nset yrange [0:{1}]\n"
                  "{4}\nset colorbox\n{8}"
                  "unset multiplot\n",
                  title, T, nmin, nmax, sim::viridis_palette, 450 * std::max<Index>(V, 2), maps, snapshots, right),
      "evolution.png"});
  figures.draw({
      "diagnostics.gp",
      fmt::format("if (!exists(\"outfile\")) outfile = 'diagnostics.png'\n"
                  "set terminal pngcairo size 1000,800\nset output outfile\n"
                  "set datafile separator ','\nset xlabel 't (dimensionless)'\n"
                  "set multiplot layout 2,1 title '{0}'\n"
                  "set logscale y\nset format y '%.0e'\nset ylabel 'E_{{b}}(t), eq. (52)'\n"
                  "set title 'relative error E_{{b}}(m T_{{b}})'\n"
                  "plot 'evolution.csv' skip 1 u 1:($2 > 1e-16 ? $2 : 1e-16) w l lc 'blue' notitle\n"
                  "unset logscale y\nset format y '%g'\nset ylabel 'site n'\n"
                  "set title 'breather position (amplitude dip over each period; unwrapped)'\n"
                  "plot 'evolution.csv' skip 1 u 1:5 w l lc 'red' notitle\n"
                  "unset multiplot\n",
                  title),
      "diagnostics.png"});
  figures.finish(summary);
  sim::write_file_atomic(dir, "summary.json", summary.dump(2) + "\n");
}

void run_evolve(const DarkArgs& a) {
  validate_job(a, DarkJob::evolve);
  Solved s = solve(a);
  const Eigen::VectorXd z0 = s.shooting.z_from_unknowns(s.newton.q);
  const DarkEvolution e = evolve_dark_breather(a.p, z0, a.omega_b, a.t_end, a.samples, s.shooting.integration());
  json j = base_json(a, s);
  const auto& first = e.periods.front();
  const auto& last = e.periods.back();
  double max_shift = 0, max_E = 0;
  for (const auto& r : e.periods) {
    max_shift = std::max(max_shift, std::abs(r.position - first.position));
    max_E = std::max(max_E, r.E_b);
  }
  j["t_end"] = last.t;
  j["periods"] = e.periods.size();
  j["period"] = e.period;
  j["E_b_first_period"] = first.E_b;
  j["E_b_end"] = last.E_b;
  j["E_b_max"] = max_E;
  j["C_x_first_period"] = first.C_x;
  j["C_x_end"] = last.C_x;
  j["position_first_period"] = first.position;
  j["position_end"] = last.position;
  j["centre_drift"] = std::abs(last.position - first.position);
  j["max_centre_shift"] = max_shift;
  j["depth_first_period"] = first.depth;
  j["depth_end"] = last.depth;
  j["max_strain"] = e.max_strain;
  j["samples_per_period"] = a.samples;
  if (!a.out.empty())
    write_evolution(a.out, e, {{"x", "strain x_{n}"}, {"y", "strain y_{n}"}},
                    fmt::format("{} {}-centred dark breather, ρ = {:.4g}, ω_{{b}} = {:g}", a.branch, a.center, a.p.rho, a.omega_b),
                    j);
  std::printf("%s\n", j.dump(a.json_out ? -1 : 2).c_str());
}

// ---- Any model file (--model): the same jobs on the model's generated lattice kernels. ----

// A model's dark job after every check: the model, its kernels, the defocusing edge and seed.
struct ModelDarkJob {
  Model model;
  LatticeCode code;  // compiled-in, or compiled at run time for a user's file (kept loaded here)
  const lrchain_lattice_kernels* kernels;
  ModelDarkAnsatz ansatz;
  sim::dark::ContactBonds contacts;  // one-sided contacts (empty: a smooth model)
};

// Loads --model/--set and checks every option of the job before anything is computed or written
// (InvalidParameter/InputError: exit 2): the defocusing edge, omega_b, sites, window, memory, --out.
ModelDarkJob validate_model_job(const DarkArgs& a, DarkJob job, const CLI::App& cmd) {
  parse_dark_center(a.center);
  parse_shooting_mode(a.mode);
  Model model = load_selected_model(a.model, cmd, a.p, true);
  LatticeCode code = lattice_kernels_for(a.model, model);
  const lrchain_lattice_kernels& kernels = *code.kernels;
  const std::optional<Index> given = a.branch_given ? std::optional(model.branch(a.branch)) : std::nullopt;
  ModelDarkAnsatz ansatz = make_model_dark_ansatz(model, kernels, defocusing_edge(model, given), a.omega_b);
  check_dark_sites(ansatz, a.sites);
  sim::dark::ContactBonds contacts =
      sim::dark::model_contact_bonds(kernels, sim::lattice_parameters(model), ansatz.mean_flow);
  const double period = 2 * std::numbers::pi / a.omega_b;
  double periods = 0;
  if (job == DarkJob::branch) {
    checked_finite(a.ds, "ds");
    if (!(a.ds > 0 && a.ds <= 1)) throw InvalidParameter("ds", "must be in (0, 1] (it adapts within [1e-5, 1])");
    checked_finite(a.omega_min, "omega-min");
    checked_finite(a.omega_max, "omega-max");
    if (!(a.omega_min < a.omega_b)) throw InvalidParameter("omega-min", "must lie below omega-b");
    if (a.omega_max != 0 && !(a.omega_max > a.omega_b))
      throw InvalidParameter("omega-max", "must be 0 (the band edge, or none above it) or a frequency above omega-b");
  }
  if (job == DarkJob::evolve) {
    if (!(std::isfinite(a.t_end) && a.t_end >= period))
      throw InvalidParameter("t-end", fmt::format("must be a finite time >= one period T_b = 2 pi/omega_b = {:.6g}", period));
    periods = double(config::checked_option_count(a.t_end, period, config::dark_periods, "t-end"));
  }
  // The estimate counts two fields per site: scale the sites to the model's number of fields.
  const double sites = double(a.sites) * double(kernels.fields) / 2.0;
  const sim::ResourceEstimate e = sim::estimate_dark_breather(sites, true, period, periods);
  sim::check_memory(e, a.max_memory, e.dominant == "periods" ? "t-end" : "sites",
                    e.dominant == "periods" ? "lower t-end" : "lower sites");
  if (!a.out.empty()) {
    std::error_code ec;
    if (std::filesystem::exists(a.out, ec) && !std::filesystem::is_directory(a.out, ec))
      throw InputError("--out '" + a.out + "' exists and is not a directory");
    sim::check_output_space(e, a.out, "out", "choose another --out");
  }
  return {std::move(model), std::move(code), &kernels, std::move(ansatz), std::move(contacts)};
}

// Names of the lattice variables (CSV columns): strains r, w_f of translation-invariant models,
// displacements u_f of on-site models.
std::vector<std::string> model_variables(const ModelDarkJob& m) {
  std::vector<std::string> names;
  for (int f = 0; f < m.kernels->fields; ++f)
    names.push_back(m.ansatz.mean_flow ? (f == 0 ? "r" : fmt::format("w{}", f)) : fmt::format("u{}", f));
  return names;
}

// What each lattice variable is: r[n] = u0[n] - u0[n-1], w_f[n] = u_f[n] - u0[n] (strain form) or u_f[n].
std::vector<std::string> model_variable_meanings(const ModelDarkJob& m) {
  std::vector<std::string> meanings;
  for (int f = 0; f < m.kernels->fields; ++f)
    meanings.push_back(m.ansatz.mean_flow ? (f == 0 ? "r[n] = u0[n] - u0[n-1]" : fmt::format("w{0}[n] = u{0}[n] - u0[n]", f))
                                          : fmt::format("u{}[n]", f));
  return meanings;
}

// The model's one-sided contact bonds by name (an empty list for a smooth model).
json contact_names(const sim::dark::ContactBonds& contacts) {
  json names = json::array();
  for (const auto& bond : contacts) names.push_back(bond.name);
  return names;
}

json model_base_json(const DarkArgs& a, const ModelDarkJob& m, const NewtonResult& newton) {
  json hist = json::array();
  for (const auto& r : newton.history) hist.push_back(r.residual);
  json variables = model_variable_meanings(m);
  return {{"model", model_json(m.model)}, {"branch", m.model.definition().branch_names.at(m.ansatz.branch)},
          {"theta", m.ansatz.theta}, {"center", a.center}, {"sites", a.sites}, {"mode", a.mode},
          {"omega_b", a.omega_b}, {"omega_edge", m.ansatz.omega}, {"curvature", m.ansatz.curvature},
          {"h_tilde", m.ansatz.h_tilde}, {"lambda", m.ansatz.mean_flow ? json(m.ansatz.lambda) : json(nullptr)},
          {"lattice_form", m.ansatz.mean_flow ? "strain" : "displacement"}, {"variables", variables},
          {"one_sided_contacts", contact_names(m.contacts)},
          {"contact_changes_located", !m.contacts.empty()},
          {"newton_converged", newton.converged}, {"newton_iterations", newton.history.empty() ? 0 : newton.history.size() - 1},
          {"newton_residuals", hist}, {"failure", nullptr}, {"provenance", provenance_json()}};
}

// Newton from the model's seed; on failure prints the JSON (converged false) and throws (exit 3).
NewtonResult model_newton(const DarkArgs& a, const ModelDarkJob& m, const ModelDarkShooting& shooting) {
  NewtonOptions o;
  if (!a.quiet)
    o.progress = print_newton_progress;
  NewtonResult res = newton_solve(shooting, model_dark_seed(m.ansatz, parse_dark_center(a.center), a.sites), a.omega_b, o);
  if (!res.converged) {
    const std::string message = newton_failure_message(res, a.omega_b);
    json j = model_base_json(a, m, res);
    j["failure"] = {{"kind", "newton"}, {"message", message}};
    std::printf("%s\n", j.dump(a.json_out ? -1 : 2).c_str());
    throw NumericalFailure(message);
  }
  return res;
}

void run_model_job(const DarkArgs& a, DarkJob job, const CLI::App& cmd) {
  const ModelDarkJob m = validate_model_job(a, job, cmd);
  const ModelDarkShooting shooting(*m.kernels, sim::lattice_parameters(m.model), a.sites, m.ansatz.mean_flow,
                                   parse_shooting_mode(a.mode), {}, m.contacts);
  const NewtonResult newton = model_newton(a, m, shooting);
  json j = model_base_json(a, m, newton);
  const Eigen::VectorXd& z0 = newton.q;
  if (job == DarkJob::branch) {  // the start's contact changes are its branch point's
    continue_and_report(a, shooting, z0, m.ansatz.omega, j, m.model.name(), true);
    return;
  }
  j["contact_changes_per_period"] = count_json(shooting.contact_changes_per_period(z0, a.omega_b));
  const std::vector<std::string> variables = model_variables(m);
  const Index N = a.sites;
  if (job == DarkJob::evolve) {
    StopSignals signals;
    const DarkEvolution e = evolve_dark_orbit(shooting.advance(), z0, N, a.omega_b, a.t_end, a.samples, StopSignals::flag());
    if (e.periods.empty()) throw Interrupted(StopSignals::received(), "interrupted before the first period");
    double max_E = 0, max_shift = 0;
    for (const auto& r : e.periods) {
      max_E = std::max(max_E, r.E_b);
      max_shift = std::max(max_shift, std::abs(r.position - e.periods.front().position));
    }
    j["t_end"] = e.periods.back().t;
    j["periods"] = e.periods.size();
    j["period"] = e.period;
    j["E_b_first_period"] = e.periods.front().E_b;
    j["E_b_end"] = e.periods.back().E_b;
    j["E_b_max"] = max_E;
    j["C_x_first_period"] = e.periods.front().C_x;
    j["C_x_end"] = e.periods.back().C_x;
    j["position_first_period"] = e.periods.front().position;
    j["position_end"] = e.periods.back().position;
    j["centre_drift"] = std::abs(e.periods.back().position - e.periods.front().position);
    j["max_centre_shift"] = max_shift;
    j["depth_first_period"] = e.periods.front().depth;
    j["depth_end"] = e.periods.back().depth;
    j["samples_per_period"] = a.samples;
    if (!a.out.empty()) {
      std::vector<EvolutionVariable> fields;
      const std::vector<std::string> meanings = model_variable_meanings(m);
      for (std::size_t v = 0; v < variables.size(); ++v) fields.push_back({variables[v], gnuplot_literal(meanings[v])});
      write_evolution(a.out, e, fields,
                      fmt::format("{} {} {}-centred dark breather, ω_{{b}} = {:g}", gnuplot_literal(m.model.name()),
                                  gnuplot_literal(m.model.definition().branch_names.at(m.ansatz.branch)), a.center,
                                  a.omega_b),
                      j);
    }
    std::printf("%s\n", j.dump(a.json_out ? -1 : 2).c_str());
    if (StopSignals::received() != 0)
      throw Interrupted(StopSignals::received(), fmt::format("interrupted after {} periods", e.periods.size()));
    return;
  }
  DarkMeasures measures;
  shooting.measure(z0, a.omega_b, measures);
  j["measures"] = measures_json(measures);
  if (!m.ansatz.mean_flow || m.kernels->fields < 2) j["measures"]["K_y"] = j["measures"]["C_y"] = nullptr;
  FloquetResult f;
  if (job == DarkJob::floquet) {
    f = floquet_from_monodromy(shooting.monodromy(z0, a.omega_b));
    j["monodromy"] = "full period";
    j["floquet"] = floquet_json(f, true);
  }
  if (!a.out.empty()) {
    const sim::OutputLock lock(a.out);
    sim::Figures figures(a.out);
    const Eigen::VectorXd seed = model_dark_seed(m.ansatz, parse_dark_center(a.center), N);
    std::vector<double> state(2 * std::size_t(z0.size()), 0.0);
    std::copy(z0.data(), z0.data() + z0.size(), state.begin());
    shooting.orbit().integrate(state, 0.0, 2 * std::numbers::pi / a.omega_b);
    std::ostringstream os;
    os << "n";
    for (const auto& v : variables) os << "," << v << "_0," << v << "_seed," << v << "_T";
    os << "\n";
    for (Index i = 0; i < N; ++i) {
      os << i - (N - 1) / 2;
      for (std::size_t v = 0; v < variables.size(); ++v) {
        const Index at = Index(v) * N + i;
        os << fmt::format(",{:.17g},{:.17g},{:.17g}", z0(at), seed(at), state[std::size_t(at)]);
      }
      os << "\n";
    }
    sim::write_file_atomic(a.out, "profile.csv", os.str());
    std::string plot = "plot ";
    for (std::size_t v = 0; v < variables.size(); ++v)
      plot += fmt::format("{0}'profile.csv' skip 1 u 1:{1} w lp pt 3 t '{2}(0)', '' skip 1 u 1:{3} w p pt 4 ps 1.5 t "
                          "'{2}(T_{{b}})', '' skip 1 u 1:{4} w p pt 6 t '{2} seed'",
                          v == 0 ? "" : ", ", 2 + 3 * v, gnuplot_literal(variables[v]), 4 + 3 * v, 3 + 3 * v);
    figures.draw({"profile.gp",
                  fmt::format("if (!exists(\"outfile\")) outfile = 'profile.png'\n"
                              "set terminal pngcairo size 1000,700\nset output outfile\n"
                              "set datafile separator ','\nset xlabel 'site n'\nset ylabel 'lattice variables: strains or displacements (model units)'\n"
                              "set key outside\nset title '{} dark breather ({} centred), ω_{{b}} = {:.5f}: Z(0), Z(T_{{b}}), seed'\n{}\n",
                              gnuplot_literal(m.model.name()), a.center, a.omega_b, plot),
                  "profile.png"});
    if (job == DarkJob::floquet) write_multipliers(a.out, "multipliers", f, a.omega_b, figures);
    figures.finish(j);
  }
  std::printf("%s\n", j.dump(a.json_out ? -1 : 2).c_str());
}

// The resonant chain through Params, or (--model) any model file.
void dispatch(const DarkArgs& a, DarkJob job, const CLI::App& cmd) {
  refuse_without_out(cmd, a.out, {"--format", "--figure-format"});
  if (a.model.file.empty()) {
    if (!a.model.set.empty()) throw InputError("--set takes the parameters of a --model FILE; give --model");
    if (job == DarkJob::branch) run_continue(a);
    else if (job == DarkJob::evolve) run_evolve(a);
    else run_solve(a, job == DarkJob::floquet);
    return;
  }
  if (a.full_monodromy) throw InputError("--full-monodromy: with --model the Floquet multipliers always come from the full-period monodromy");
  if (a.format == "hdf5") throw InputError("--format hdf5 is not available with --model (it writes CSV and figures; use --format csv)");
  run_model_job(a, job, cmd);
}

}  // namespace

void register_dark(CLI::App& app) {
  auto* dark = app.add_subcommand(
      "dark", "Exact stationary dark breathers (Secs. 5.3-5.4): shooting Newton on the period-T_b map, "
              "continuation in omega_b, Floquet stability");
  dark->require_subcommand(1);
  add_examples(*dark, {"lrchain dark continue --rho 1/3 --branch optical --omega-b 2.42 --points 12 --out out/dark",
                       "lrchain dark solve --model klein_gordon --set b=-1/2 --omega-b 1.17 --sites 61"});
  auto args = std::make_shared<DarkArgs>();
  auto* solve_cmd = dark->add_subcommand("solve", "Newton solve from the eq:xy_app seed");
  add_common(*solve_cmd, *args);
  add_examples(*solve_cmd, {"lrchain dark solve --rho 1/3 --branch optical --center bond --omega-b 2.44 --out out/dark-solve",
                            "lrchain dark solve --model klein_gordon --set b=-1/2 --omega-b 1.17 --sites 61"});
  solve_cmd->callback([args, solve_cmd] { dispatch(*args, DarkJob::solve, *solve_cmd); });
  auto* floq = dark->add_subcommand("floquet", "Solve, then the Floquet multipliers of the monodromy matrix (Sec. 5.4)");
  add_common(*floq, *args);
  floq->add_flag("--full-monodromy", args->full_monodromy,
                 "integrate the full period (check of the reversible reduction)");
  add_examples(*floq, {"lrchain dark floquet --rho 1/3 --center bond --omega-b 2.44 --sites 51",
                       "lrchain dark floquet --model diatomic_chain --omega-b 1.33 --sites 41"});
  floq->callback([args, floq] { dispatch(*args, DarkJob::floquet, *floq); });
  auto* cont = dark->add_subcommand(
      "continue", "Pseudo-arclength continuation in omega_b through turning points, Floquet at every point");
  add_common(*cont, *args);
  add_integer(*cont, "--points", args->points, config::dark_points.least, config::dark_points.most, "maximum number of branch points, the first included (default 100; e.g. --points 10 for a quick run)");
  add_number(*cont, "--ds", args->ds, "initial pseudo-arclength step in (Z(0), omega_b), dimensionless, adapted between 1e-5 and 1 (default 0.1)");
  add_number(*cont, "--omega-min", args->omega_min, "stop when omega_b falls below this (dimensionless frequency; default 0)");
  add_number(*cont, "--omega-max", args->omega_max, "stop when omega_b rises above this (dimensionless frequency, at most twice the top of the optical band; default: the band edge omega(pi))");
  add_examples(*cont, {"lrchain dark continue --rho 1/3 --branch optical --center bond --omega-b 2.44 --points 10 --out out/dark"});
  cont->callback([args, cont] { dispatch(*args, DarkJob::branch, *cont); });
  auto* evo = dark->add_subcommand(
      "evolve", "Solve, then integrate eq:Hertzd0S from the solution: space-time x_n, y_n, E_b(t), breather position (Figs. 21, 22, 25)");
  add_common(*evo, *args);
  add_number(*evo, "--t-end", args->t_end, "integration time (dimensionless, time unit of Sec. 2), at least one period T_b (required)")->required();
  add_integer(*evo, "--samples", args->samples, config::dark_samples.least, config::dark_samples.most,
              "samples of x_n(t) per period for the amplitudes of the position measure (default 24, >= 4)");
  add_examples(*evo, {"lrchain dark evolve --rho 1/3 --center bond --omega-b 2.44 --t-end 500 --out out/dark-evolve"});
  evo->callback([args, evo] { dispatch(*args, DarkJob::evolve, *evo); });
  for (auto* sub : {solve_cmd, floq, cont})
    sub->add_option("--format", args->format,
                    "data files in --out: csv (CSV and figures; default) or hdf5 (also result.h5: profiles or the "
                    "branch, Floquet multipliers as complex numbers; not with --model)")
        ->check(CLI::IsMember({"csv", "hdf5"}).description(""))
        ->type_name("csv|hdf5");
}

}  // namespace lrchain::cli

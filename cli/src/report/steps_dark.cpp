// Reproduce steps: exact stationary dark breathers of Secs. 5.3-5.4 (Figs. 17-25) - solutions at
// omega_b = 2.42, branches continued in omega_b through the turning point, Floquet stability.
#include <fmt/format.h>

#include "experiment_runs.hpp"
#include "lrchain_process.hpp"
#include "steps.hpp"

namespace lrchain::report {

namespace {

using nlohmann::json;

// Quick branches use 61 sites per field instead of the default 101 and stop once the points the
// report's rows read are computed (measured: each point costs ~0.2 s of CPU time at 61 sites; the
// rows read the same values as with 101 sites: turning point 2.37416 vs 2.37411, period doubling,
// the rho = 1 real instability near 2.207 only on the site-centred branch, rho = 10 oscillatory at
// the first point, rho = 0.1 real-dominated weakly nonlinear points). --full keeps 101 sites.
constexpr int quick_sites = 61;

struct BranchRun {
  std::string sub;      // output sub-directory under dark/
  std::string rho, edge, center, start;
  int quick_points, full_points;
};

json run_branch(const StepContext& ctx, const BranchRun& b, Section& s, CsvTable& table) {
  const auto dir = ctx.out / "dark" / b.sub;
  const int points = ctx.full ? b.full_points : b.quick_points;
  // A larger arclength step (--ds 0.2) does not shorten the quick branches: the corrector then
  // needs 6-7 chord iterations, the step shrinks back, and 26 points at rho = 1 stopped at
  // omega_b = 2.233, short of 2.207. The quick branches keep the default step.
  std::vector<std::string> args = {"dark",     "continue", "--rho",    b.rho,   "--branch",
                                   b.edge,     "--center", b.center,   "--omega-b", b.start,
                                   "--points", std::to_string(points), "--quiet", "--out", dir.string()};
  if (!ctx.full) args.insert(args.end() - 3, {"--sites", std::to_string(quick_sites)});
  json j = run_lrchain(ctx, args, dir, "summary", s.commands);
  table = read_csv(dir / "branch.csv");
  s.links.push_back("dark/" + b.sub + "/branch.csv");
  s.links.push_back("dark/" + b.sub + "/floquet_moduli.csv");
  return j;
}

std::string branch_facts(const json& j, const CsvTable& t) {
  double lo = 1e300, hi = -1e300, worst = 0;
  for (std::size_t i = 0; i < t.cells.size(); ++i) {
    lo = std::min(lo, t.number(i, "omega_b"));
    hi = std::max(hi, t.number(i, "omega_b"));
    worst = std::max(worst, t.number(i, "E_b"));
  }
  return fmt::format("{} points for omega_b in [{:.5f}, {:.5f}], {} sites per field; stop: {}; max E_b(T_b) = {:.1e}.",
                     t.cells.size(), lo, hi, j.value("sites", 0), j.value("stop_reason", std::string("?")), worst);
}

struct BranchFigures {
  std::string branch_figure, branch_caption, moduli_figure;
};

// floquet_moduli.png draws a second (bottom) panel only for a branch continued past its turning point.
std::string moduli_caption(bool past_turning_point) {
  return std::string("Moduli of the Floquet multipliers outside the unit circle versus omega_b, ") +
         (past_turning_point ? "weakly (top) and strongly (bottom) nonlinear parts"
                             : "weakly nonlinear part only (this run stops before the turning point)") +
         "; blue complex, red real > 0, green real < 0.";
}

// A section for one continued branch: runs it, states what was computed, adds both figures.
Section branch_section(const StepContext& ctx, const std::string& id, const std::string& title,
                       const BranchRun& run, const BranchFigures& figures, CsvTable& table, json& summary) {
  Section s;
  s.id = id;
  s.title = title;
  summary = run_branch(ctx, run, s, table);
  s.intro = "Pseudo-arclength continuation in omega_b from " + run.start + ", Floquet multipliers at every point. " +
            branch_facts(summary, table) +
            (ctx.full ? "" : fmt::format(" Quick run: {} sites and at most {} points (--full: 101 sites, {} points).",
                                         quick_sites, run.quick_points, run.full_points));
  const std::string dir = "dark/" + run.sub + "/";
  s.figures.push_back({dir + "branch.png", figures.branch_figure, figures.branch_caption});
  const bool turned = !summary.value("turning_points", json::array()).empty();
  s.figures.push_back({dir + "floquet_moduli.png", figures.moduli_figure, moduli_caption(turned)});
  return s;
}

Section solutions(const StepContext& ctx) {
  Section s;
  s.id = "dark_solutions";
  s.title = "Dark breathers at omega_b = 2.42, rho = 1/3 (Sec. 5.3, Fig. 17)";
  s.intro = "Shooting Newton on the period map of eq:Hertzd0S with periodic ends, seeded by eq:xy_app; "
            "E_b(T_b) is eq:relerr after one period.";
  for (const std::string center : {"bond", "site"}) {
    const auto dir = ctx.out / "dark" / ("solve_" + center);
    const json j = run_lrchain(ctx,
                               {"dark", "solve", "--rho", "1/3", "--branch", "optical", "--center", center, "--omega-b",
                                "2.42", "--quiet", "--out", dir.string()},
                               dir, "summary", s.commands);
    const double eb = j.contains("measures") ? j["measures"].value("E_b", not_computed) : not_computed;
    s.rows.push_back(below_row(center + "-centred solution: E_b(T_b)", "Sec. 5.3", "< 3e-9", 3e-9, eb,
                               fmt::format("{} sites per field", j.value("sites", 0))));
    s.figures.push_back({"dark/solve_" + center + "/profile.png", "fig:opt_r03_wb242, " +
                         std::string(center == "bond" ? "left" : "right"),
                         center + "-centred dark breather at omega_b = 2.42: solution, after one period, and the seed eq:xy_app."});
    s.links.push_back("dark/solve_" + center + "/summary.json");
  }
  return s;
}

// Largest value of `column` over the branch points (the strongest instability of that kind).
double branch_max(const CsvTable& t, const std::string& column) {
  double m = not_computed;
  for (std::size_t i = 0; i < t.cells.size(); ++i) {
    const double v = t.number(i, column);
    if (!(v <= m)) m = v;
  }
  return m;
}

Section optical_bond(const StepContext& ctx) {
  CsvTable t;
  json j;
  Section s = branch_section(
      ctx, "dark_optical_bond", "Optical bond-centred branch, rho = 1/3 (Figs. 18 left, 20 left)",
      {"optical_bond_rho_1_3", "1/3", "optical", "bond", "2.44", 60, 140},
      {"fig:r03_norm, left",
       "Renormalised l2 norm (eq:l2norm) of bond-centred optical dark breathers versus omega_b; red: real "
       "instability; vertical line: omega_opt = 2.4495.",
       "fig:opt_floq_r03, left"},
      t, j);
  double turning = not_computed;
  for (const auto& tp : j.value("turning_points", json::array()))
    if (std::isnan(turning) || std::abs(tp.get<double>() - 2.37) < std::abs(turning - 2.37)) turning = tp.get<double>();
  s.rows.push_back(equals_row("turning point of the branch", "Sec. 5.3, Fig. 18", "omega_b ~ 2.37", 2.37, turning, 0.005));
  s.rows.push_back(qualitative_row("largest period-doubling multiplier modulus (real < -1)", "Sec. 5.4, Fig. 20",
                                   "period-doubling instability (bond-centred)", Claim::above, 1.0 + 1e-6,
                                   branch_max(t, "max_period_doubling")));
  return s;
}

Section optical_site(const StepContext& ctx) {
  CsvTable t;
  json j;
  return branch_section(ctx, "dark_optical_site", "Optical site-centred branch, rho = 1/3 (Figs. 18 right, 20 right)",
                        {"optical_site_rho_1_3", "1/3", "optical", "site", "2.44", 45, 140},
                        {"fig:r03_norm, right",
                         "Renormalised l2 norm of site-centred optical dark breathers versus omega_b; red: real instability.",
                         "fig:opt_floq_r03, right"},
                        t, j);
}

Section acoustic_bond(const StepContext& ctx) {
  CsvTable t;
  json j;
  return branch_section(ctx, "dark_acoustic_bond", "Acoustic bond-centred branch, rho = 1/3 (Fig. 23)",
                        {"acoustic_bond_rho_1_3", "1/3", "acoustic", "bond", "1.41", 50, 150},
                        {"fig:acs_floq_bc_r03, left",
                         "Renormalised l2 norm of bond-centred acoustic dark breathers versus omega_b (omega_acs = 1.4142).",
                         "fig:acs_floq_bc_r03, right"},
                        t, j);
}

// Largest real multiplier > 0 at the weakly nonlinear branch point closest to omega (within
// 0.01, before the turning point); sets `at` to that point's omega_b.
double real_multiplier_near(const CsvTable& t, double omega, double& at) {
  double max_real = not_computed;
  at = not_computed;
  for (std::size_t i = 0; i < t.cells.size(); ++i) {
    const double w = t.number(i, "omega_b");
    if (i > 0 && w > t.number(i - 1, "omega_b")) break;  // past the turning point
    if (std::abs(w - omega) < 0.01 && (std::isnan(at) || std::abs(w - omega) < std::abs(at - omega)))
      at = w, max_real = t.number(i, "max_real");
  }
  return max_real;
}

Section rho1(const StepContext& ctx, const std::string& center) {
  const bool bond = center == "bond";
  const std::string side = bond ? "left" : "right";
  CsvTable t;
  json j;
  Section s = branch_section(
      ctx, "dark_rho1_" + center, "Optical " + center + "-centred branch, rho = 1 (Figs. 19, 24" + (bond ? ", 25)" : ")"),
      {"optical_" + center + "_rho_1", "1", "optical", center, "2.28", bond ? 40 : 44, 140},
      {"fig:r1_norm, " + side,
       "Renormalised l2 norm of " + center + "-centred optical dark breathers, rho = 1 (omega_opt = 2.2882); red: "
       "real instability.",
       "fig:opt_floq_r1, " + side},
      t, j);
  double at = not_computed;
  const double max_real = real_multiplier_near(t, 2.207, at);
  Comparison real = qualitative_row(
      "largest real multiplier > 0 at omega_b ~ 2.207 (weakly nonlinear, " + center + "-centred)", "Sec. 5.4, Fig. 25",
      "real instability sets the breather in motion", Claim::above, 1.0 + 1e-6, max_real,
      std::isnan(at) ? "the branch did not reach 2.207" : fmt::format("branch point omega_b = {:.5f}", at));
  s.rows.push_back(bond ? unresolved(real, "Real instability") : real);
  return s;
}

Section rho10_optical(const StepContext& ctx) {
  CsvTable t;
  json j;
  Section s = branch_section(ctx, "dark_rho10_optical", "Optical bond-centred branch, rho = 10 (Sec. 5.4)",
                             {"optical_bond_rho_10", "10", "optical", "bond", "2.235", 20, 120},
                             {"Sec. 5.3 (no figure in the paper)",
                              "Renormalised l2 norm of bond-centred optical dark breathers, rho = 10 (omega_opt = 2.2406).",
                              "Sec. 5.4 (no figure in the paper)"},
                             t, j);
  // "the oscillatory instability appears to set in already in the immediate vicinity of the
  // linear limit at the edge of the optical band": the first branch point, 0.0056 below the edge.
  s.rows.push_back(qualitative_row("largest oscillatory multiplier modulus at the branch point nearest the band edge",
                                   "Sec. 5.4", "oscillatory instability next to the edge", Claim::above, 1.0 + 1e-6,
                                   t.cells.empty() ? not_computed : t.number(0, "max_oscillatory"),
                                   t.cells.empty() ? "" : fmt::format("omega_b = {:.4f}, edge {:.4f}", t.number(0, "omega_b"),
                                                                      j.value("omega_edge", 0.0))));
  return s;
}

Section rho01_acoustic(const StepContext& ctx) {
  CsvTable t;
  json j;
  Section s = branch_section(ctx, "dark_rho01_acoustic", "Acoustic bond-centred branch, rho = 0.1 (Sec. 5.4)",
                             {"acoustic_bond_rho_0.1", "0.1", "acoustic", "bond", "1.85", 36, 150},
                             {"Sec. 5.3 (no figure in the paper)",
                              "Renormalised l2 norm of bond-centred acoustic dark breathers, rho = 0.1 (omega_acs = 1.8625).",
                              "Sec. 5.4 (no figure in the paper)"},
                             t, j);
  // "the real instability of some of the weakly nonlinear solutions is again more significant
  // than the oscillatory instability": weakly nonlinear points where max real > max oscillatory.
  int dominant = 0;
  for (std::size_t i = 0; i < t.cells.size(); ++i) {
    if (i > 0 && t.number(i, "omega_b") > t.number(i - 1, "omega_b")) break;  // past the turning point
    if (t.number(i, "max_real") > 1 + 1e-6 && t.number(i, "max_real") > t.number(i, "max_oscillatory")) ++dominant;
  }
  s.rows.push_back(qualitative_row("weakly nonlinear branch points where the real instability exceeds the oscillatory one",
                                   "Sec. 5.4", "some", Claim::above, 0.0, dominant));
  return s;
}

// Direct integration from an exact solution (`lrchain dark evolve`): E_b(t) (eq:relerr) and the
// position of the amplitude dip over time.
json evolve(const StepContext& ctx, Section& s, const std::string& sub, const std::string& rho,
            const std::string& center, const std::string& omega_b, const std::string& t_end) {
  const auto dir = ctx.out / "dark" / sub;
  const json j = run_lrchain(ctx,
                             {"dark", "evolve", "--rho", rho, "--branch", "optical", "--center", center, "--omega-b",
                              omega_b, "--t-end", t_end, "--samples", "12", "--quiet", "--out", dir.string()},
                             dir, "summary", s.commands);
  s.links.push_back("dark/" + sub + "/evolution.csv");
  return j;
}

Section evolution_long_lived(const StepContext& ctx) {
  Section s;
  s.id = "dark_evolution_2.4255";
  s.title = "Long-lived bond-centred dark breather, rho = 1/3, omega_b = 2.4255 (Fig. 21)";
  s.intro = "Exact solution integrated to t = 1200 with periodic ends.";
  const json j = evolve(ctx, s, "evolve_bond_2.4255", "1/3", "bond", "2.4255", "1200");
  s.rows.push_back(below_row("E_b(1200) (eq:relerr)", "Sec. 5.4", "< 2e-4", 2e-4, json_number(j, "E_b_end")));
  s.figures.push_back({"dark/evolve_bond_2.4255/evolution.png", "fig:opt_bc_r03_wb24255, right",
                       "Snapshots at t = 0 and 1200 and space-time plots of x_n and y_n (one row per period)."});
  return s;
}

Section evolution_destroyed(const StepContext& ctx) {
  Section s;
  s.id = "dark_evolution_2.40";
  s.title = "Unstable site-centred dark breather, rho = 1/3, omega_b = 2.40 (Fig. 22)";
  s.intro = "Exact solution integrated to t = 500 with periodic ends.";
  const json j = evolve(ctx, s, "evolve_site_2.40", "1/3", "site", "2.40", "500");
  s.rows.push_back(qualitative_row("E_b(500) (eq:relerr)", "Sec. 5.4, Fig. 22", "the structure is destroyed", Claim::above,
                                   1e-2, json_number(j, "E_b_end")));
  s.figures.push_back({"dark/evolve_site_2.40/evolution.png", "fig:opt_sc_r03_wb240",
                       "Snapshots at t = 0 and 500 and space-time plots of x_n, y_n: the breather breaks up."});
  return s;
}

Section evolution_moving(const StepContext& ctx) {
  Section s;
  s.id = "dark_evolution_rho1";
  s.title = "Real instability sets the breather in motion, rho = 1, omega_b = 2.207 (Fig. 25)";
  s.intro = "Site-centred exact solution (the family with the real instability at 2.207 in our computation; "
            "docs/paper-errata.md) integrated to t = 1500 (526 T_b); no perturbation, the motion grows from round-off.";
  const json j = evolve(ctx, s, "evolve_site_rho1_2.207", "1", "site", "2.207", "1500");
  s.rows.push_back(qualitative_row("distance the dark breather has moved by t = 1500 (sites)", "Sec. 5.4, Fig. 25",
                                   "set in motion", Claim::above, 1.0, json_number(j, "max_centre_shift"),
                                   "position of the amplitude dip, weighted circular mean"));
  s.figures.push_back({"dark/evolve_site_rho1_2.207/evolution.png", "fig:weak_opt_bc_r1_evol",
                       "Snapshots at t = 0 and 1500 and space-time plots of x_n, y_n: the dark breather starts to move."});
  s.figures.push_back({"dark/evolve_site_rho1_2.207/diagnostics.png", "Fig. 25, diagnostics",
                       "E_b(t) and the position of the dark breather versus time."});
  return s;
}

}  // namespace

std::vector<Step> dark_steps() {
  return {{"dark_solutions", "Dark breathers at 2.42", 1.2, solutions},
          {"dark_optical_bond", "Optical bond-centred branch", 13, optical_bond},
          {"dark_optical_site", "Optical site-centred branch", 10, optical_site},
          {"dark_acoustic_bond", "Acoustic bond-centred branch", 11, acoustic_bond},
          {"dark_rho1_bond", "Optical bond-centred branch, rho = 1", 8, [](const StepContext& c) { return rho1(c, "bond"); }},
          {"dark_rho1_site", "Optical site-centred branch, rho = 1", 10, [](const StepContext& c) { return rho1(c, "site"); }},
          {"dark_rho10_optical", "Optical branch, rho = 10", 5, rho10_optical},
          {"dark_rho01_acoustic", "Acoustic branch, rho = 0.1", 8, rho01_acoustic},
          {"dark_evolution_2.4255", "Evolution at 2.4255", 0.8, evolution_long_lived},
          {"dark_evolution_2.40", "Evolution at 2.40", 2.1, evolution_destroyed},
          {"dark_evolution_rho1", "Evolution at 2.207, rho = 1", 6.4, evolution_moving}};
}

}  // namespace lrchain::report

// `lrchain regime intervals|map|thresholds`: focusing/defocusing regimes of the NLS limit
// (Sec. 3.3, Figs. 2, 4, 5). JSON summary on stdout; data, gnuplot scripts and PNGs in --out.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <fmt/format.h>
#include <nlohmann/json.hpp>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <string>
#include <unistd.h>
#include <vector>

#include "commands.hpp"
#include "figure_format_option.hpp"
#include "lrchain/config/option_caps.hpp"
#include "lrchain/provenance_json.hpp"
#include "lrchain/errors.hpp"
#include "lrchain/regime/boundary_curves.hpp"
#include "lrchain/regime/focusing_intervals.hpp"
#include "lrchain/regime/frequency_band.hpp"
#include "lrchain/regime/paper_thresholds.hpp"
#include "lrchain/regime/regime_events.hpp"
#include "lrchain/regime/model_regime.hpp"
#include "lrchain/regime/regime_map.hpp"
#include "lrchain/sim/resource_estimate.hpp"
#include "lrchain/sim/output_files.hpp"
#include "lrchain/sim/output_lock.hpp"
#include "figure_text.hpp"
#include "help_text.hpp"
#include "model_option.hpp"
#include "options.hpp"

namespace lrchain::cli {

namespace {

using nlohmann::json;
using namespace lrchain::regime;
namespace fs = std::filesystem;

// ---- output helpers -------------------------------------------------------------------------

// Writes text to dir/name through a temporary name and a rename (never a truncated result, never
// over a device, FIFO or directory: sim::write_file_atomic).
void write_file(const fs::path& dir, const std::string& name, const std::string& text) {
  sim::write_file_atomic(dir, name, text);
}

json interval_json(const FocusingInterval& i) {
  return {{"lo", i.lo},
          {"hi", i.hi},
          {"lo_cause", std::string(to_string(i.lo_cause))},
          {"hi_cause", std::string(to_string(i.hi_cause))}};
}

json event_json(const RegimeEvent& e) {
  json causes = json::array();
  for (auto c : e.causes) causes.push_back(std::string(to_string(c)));
  json j = {{"value", e.value},
            {"kind", std::string(to_string(e.kind))},
            {"causes", causes},
            {"focusing_intervals_before", e.intervals_before},
            {"focusing_intervals_after", e.intervals_after}};
  j["theta"] = std::isfinite(e.theta) ? json(e.theta) : json(nullptr);
  return j;
}

// Pixel map as CSV "x,y,regime" in scan order (y rows, blank line between rows for gnuplot).
std::string map_csv(const RegimeMap& m, const char* xname, const char* yname) {
  std::ostringstream s;
  s.precision(8);
  s << xname << ',' << yname << ",regime\n";
  for (int j = 0; j < m.y.n; ++j) {
    for (int i = 0; i < m.x.n; ++i)
      s << m.x.at(i) << ',' << m.y.at(j) << ',' << static_cast<int>(m.at(i, j)) << '\n';
    s << '\n';
  }
  return s.str();
}

// Boundary polylines of one cause as CSV "x,y", one blank line between polylines.
std::string curves_csv(const std::vector<BoundaryCurve>& curves, BoundaryCause cause,
                       const char* xname, const char* yname, int& count) {
  std::ostringstream s;
  s.precision(15);
  s << xname << ',' << yname << '\n';
  count = 0;
  for (const auto& c : curves) {
    if (c.cause != cause) continue;
    ++count;
    for (const auto& p : c.points) s << p.x << ',' << p.y << '\n';
    s << '\n';
  }
  return s.str();
}

// gnuplot line style per cause, after the legend of Fig. 2.
std::string cause_style(BoundaryCause c) {
  switch (c) {
    case BoundaryCause::curvature_zero: return "lc rgb '#0000ff' lw 2 dt 2";
    case BoundaryCause::nonresonance2: return "lc rgb '#009900' lw 2";
    case BoundaryCause::nonresonance1: return "lc rgb '#000000' lw 2";
    case BoundaryCause::h_tilde_zero: return "lc rgb '#cc0000' lw 1.5 dt 4";
    case BoundaryCause::band_edge: return "lc rgb '#888888'";
  }
  return "";
}
std::string cause_title(BoundaryCause c) {
  switch (c) {
    case BoundaryCause::curvature_zero: return "ω″=0";
    case BoundaryCause::nonresonance2: return "c^2(1+ρ)=K_2 (nonres. 2)";
    case BoundaryCause::nonresonance1: return "nonres. 1 violated";
    case BoundaryCause::h_tilde_zero: return "h̃=0";
    case BoundaryCause::band_edge: return "band edge";
  }
  return "";
}

const char* kPalette =
    "set palette defined (-1 '#dddddd', 0 '#ffffff', 1 '#ffaacc', 2 '#000000')\n"
    "set cbrange [-1:2]\nunset colorbox\n";

// ---- regime intervals -----------------------------------------------------------------------

struct IntervalsArgs {
  Params p;
  ModelSelection model;
  std::string branch;  // empty: optical (or a model's only branch)
  int samples = 2048;
  bool json_flag = false;
};

// The resonant chain's parameters of a loaded resonant_chain model.
Params resonant_params(const Model& m) {
  return Params{m.parameter("alpha"), m.parameter("delta0"), m.parameter("kappa"), m.parameter("rho")};
}

// A branch of a model by name; empty: "optical" if the model has it, else its only branch.
Index model_branch(const Model& m, const std::string& name) {
  if (!name.empty()) return m.branch(name);
  const auto& names = m.definition().branch_names;
  if (names.size() == 1) return 0;
  return m.branch("optical");
}

// Refuses (InvalidParameter("branch")) a branch with no real positive frequency at any of `samples`
// thetas in (0, pi] (regime_functions is NaN there: omega^2 <= 0, an unstable lattice at these
// parameters): it has no regimes, and an empty list of intervals would read as "defocusing".
void refuse_branch_without_real_frequency(const Model& model, Index branch, int samples) {
  const RegimeFunctions f = regime_functions(model, branch);
  for (int k = 1; k <= samples; ++k)
    if (!std::isnan(f(M_PI * double(k) / double(samples)).curvature)) return;
  const std::string& name = model.definition().branch_names[static_cast<std::size_t>(branch)];
  throw InvalidParameter("branch", "branch '" + name + "' of model '" + model.name() +
                                       "' has no real positive frequency on (0, pi] at these parameters (omega^2 <= 0: "
                                       "the lattice is unstable), so it has no focusing or defocusing regimes");
}

void run_intervals(const IntervalsArgs& a, const CLI::App& cmd) {
  if (a.model.file.empty()) validate(a.p);  // the resonant chain's own messages
  const Model model = load_selected_model(a.model, cmd, a.p);
  RegimeStructure s;
  json out;
  if (a.model.file.empty()) {  // the resonant chain's specialised evaluators (default)
    const Params p = resonant_params(model);
    const Branch b = parse_branch(a.branch.empty() ? "optical" : a.branch);
    s = regime_structure(regime_functions(p, b), {a.samples, 1e-12});
    out = {{"branch", std::string(to_string(b))}};
  } else {
    const Index b = model_branch(model, a.branch);
    refuse_branch_without_real_frequency(model, b, a.samples);
    s = regime_structure(regime_functions(model, b), {a.samples, 1e-12});
    out = {{"branch", model.definition().branch_names[static_cast<std::size_t>(b)]}};
  }
  json intervals = json::array(), roots = json::array();
  for (const auto& i : s.intervals) intervals.push_back(interval_json(i));
  for (const auto& r : s.roots)
    roots.push_back({{"theta", r.theta}, {"cause", std::string(to_string(r.cause))}});
  out["model"] = model_json(model);
  out["intervals"] = intervals;
  out["boundaries"] = roots;
  out["theta_tolerance"] = 1e-12;
  out["provenance"] = provenance_json();
  std::cout << out.dump(a.json_flag ? -1 : 2) << '\n';
}

// ---- regime map -----------------------------------------------------------------------------

struct MapArgs {
  Params p;
  ModelSelection model;
  std::string axis;                    // --model: the parameter on x (default rho / the first)
  std::vector<std::string> axis_range;  // --model: lo hi
  std::string plane = "theta-rho";
  std::string branch = "both";
  std::string out;
  std::vector<std::string> rho_range, delta0_range, omega_range;  // lo hi (shared parser)
  int res_x = 600, res_y = 600;
  double max_memory = 0;  // bytes (--max-memory); 0: the machine's available memory
  bool delta0_log = false;
  bool no_curves = false;
  bool no_figures = false;
};

std::vector<Branch> branches_of(const std::string& text) {
  if (text == "both") return {Branch::optical, Branch::acoustic};
  return {parse_branch(text)};
}

std::vector<double> range_or(const std::vector<std::string>& given, std::vector<double> fallback,
                             const char* name) {
  if (given.empty()) return fallback;
  if (given.size() != 2) throw InvalidParameter(name, "range needs two numbers lo hi");
  const std::vector<double> r{parse_number(given[0], name), parse_number(given[1], name)};
  if (!(r[0] < r[1])) throw InvalidParameter(name, "range needs lo < hi");
  return r;
}

json map_theta_rho(const MapArgs& a, const fs::path& dir, sim::Figures& figures) {
  json files = json::array(), panels = json::array();
  std::ostringstream gp;
  const auto bs = branches_of(a.branch);
  gp << "# Regime map sign(omega'' h_tilde) over (rho, theta), cf. Fig. 2 of the paper.\n"
        "# Pink: focusing (omega'' h_tilde < 0), white: defocusing. Re-run: gnuplot "
        "regime_theta-rho.gp\n"
     << "if (!exists('outfile')) outfile = 'regime_theta-rho.png'\n"
     << "set terminal pngcairo size " << 700 * bs.size() << ",620 font 'DejaVu Sans,11'\n"
     << "set output outfile\nset datafile separator ','\n" << kPalette
     << "set multiplot\n"
     << "set xlabel 'ρ'\nset ylabel 'θ'\n"
        "set key top right opaque box font ',9'\n";
  const double panel_w = 1.0 / static_cast<double>(bs.size());
  for (std::size_t k = 0; k < bs.size(); ++k) {
    const Branch b = bs[k];
    const std::string bn(to_string(b));
    const auto rr =
        range_or(a.rho_range, b == Branch::optical ? std::vector<double>{0.01, 30.0}
                                                   : std::vector<double>{0.01, 2.5},
                 "rho-range");
    const GridAxis rho{rr[0], rr[1], a.res_x}, theta{std::numbers::pi / a.res_y, std::numbers::pi,
                                                     a.res_y};
    const auto t0 = std::chrono::steady_clock::now();
    const RegimeMap m = theta_rho_map(a.p, b, rho, theta);
    const double map_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const std::string mapfile = "regime_theta-rho_" + bn + ".csv";
    write_file(dir, mapfile, map_csv(m, "rho", "theta"));
    files.push_back(mapfile);
    // Inset of the narrow acoustic region at small rho (as in Fig. 2), from a finer map.
    const bool inset = b == Branch::acoustic && rr[0] < 0.3 && rr[1] > 0.35;
    const double in_lo = std::max(rr[0], 0.04), in_hi = 0.35, in_theta = 1.6;
    gp << "set origin " << k * panel_w << ",0\nset size " << panel_w << ",1\n"
       << fmt::format("set title '{} branch (α = {:.4g}, δ_0 = {:.4g}, κ = {:.4g})'\n", bn, a.p.alpha, a.p.delta0,
                      a.p.kappa)
       << "set xrange [" << rr[0] << ":" << rr[1] << "]\nset yrange [0:pi]\n"
       << (b == Branch::acoustic ? "set key bottom left\n" : "set key top right\n");
    if (inset)
      gp << "set object 1 rect from " << in_lo << "," << in_theta << " to " << in_hi
         << ",pi front fs empty border lc rgb '#000000' lw 1\n";
    std::ostringstream plot;
    plot << "plot '" << mapfile << "' using 1:2:3 with image notitle";
    json curves_info = json::object();
    if (!a.no_curves) {
      const auto t1 = std::chrono::steady_clock::now();
      const auto curves = boundary_curves(a.p, b, ParameterAxis::rho, rr[0], rr[1]);
      curves_info["seconds"] =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - t1).count();
      for (BoundaryCause c : kSmoothCauses) {
        int n = 0;
        const std::string csv = curves_csv(curves, c, "rho", "theta", n);
        curves_info[std::string(to_string(c))] = n;
        if (n == 0) continue;
        const std::string f = "boundary_theta-rho_" + bn + "_" + std::string(to_string(c)) + ".csv";
        write_file(dir, f, csv);
        files.push_back(f);
        plot << ", \\\n  '" << f << "' using 1:2 with lines " << cause_style(c) << " title \""
             << cause_title(c) << "\"";
      }
    }
    gp << plot.str() << "\n";
    if (inset) {
      const RegimeMap zoom = theta_rho_map(a.p, b, {in_lo, in_hi, 300}, {in_theta, std::numbers::pi, 300});
      const std::string zf = "regime_theta-rho_" + bn + "_inset.csv";
      write_file(dir, zf, map_csv(zoom, "rho", "theta"));
      files.push_back(zf);
      std::string zplot = plot.str();
      zplot.replace(zplot.find(mapfile), mapfile.size(), zf);
      gp << "unset object 1\nset origin " << k * panel_w + 0.45 * panel_w << ",0.14\nset size "
         << 0.5 * panel_w << ",0.45\nunset title\nunset xlabel\nunset ylabel\nunset key\n"
         << "set xrange [" << in_lo << ":" << in_hi << "]\nset yrange [" << in_theta << ":pi]\n"
         << "set xtics 0.1 font ',8'\nset ytics 0.5 font ',8'\n"
         << zplot << "\n"
         << "set xlabel 'ρ'\nset ylabel 'θ'\nset key\nset xtics auto\n"
            "set ytics auto\n";
    }
    int focusing = 0;
    for (auto v : m.values) focusing += v == PixelRegime::focusing;
    panels.push_back({{"branch", bn},
                      {"rho_range", rr},
                      {"resolution", {a.res_x, a.res_y}},
                      {"map_seconds", map_s},
                      {"focusing_fraction", double(focusing) / m.values.size()},
                      {"boundary_polylines", curves_info}});
  }
  gp << "unset multiplot\n";
  write_file(dir, "regime_theta-rho.gp", gp.str());
  files.push_back("regime_theta-rho.gp");
  json out = {{"plane", "theta-rho"}, {"panels", panels}};
  if (!a.no_figures) {
    const bool ok = figures.draw_written("regime_theta-rho.gp", "regime_theta-rho.png");
    if (ok) files.push_back(sim::figure_file_name("regime_theta-rho.png"));
    out["png"] = ok;
  }
  out["files"] = files;
  return out;
}

json map_delta0_omega(const MapArgs& a, const fs::path& dir, sim::Figures& figures) {
  json files = json::array(), panels = json::array();
  const Branch b = parse_branch(a.branch);
  const std::string bn(to_string(b));
  const auto dr = range_or(a.delta0_range, {0.001, 1.0}, "delta0-range");
  const GridAxis delta0{dr[0], dr[1], a.res_x, a.delta0_log};
  validate(delta0, "delta0");
  // omega range: the union of the bands over the delta0 range (bands grow with delta0).
  Params plo = with_parameter(a.p, ParameterAxis::delta0, dr[0]);
  Params phi = with_parameter(a.p, ParameterAxis::delta0, dr[1]);
  const FrequencyBand blo = frequency_band(plo, b), bhi = frequency_band(phi, b);
  const double wmax = std::max(blo.hi, bhi.hi);
  const auto wr =
      range_or(a.omega_range, {b == Branch::optical ? 0.98 * blo.lo : 0.0, 1.02 * wmax},
               "omega-range");
  const GridAxis omega{wr[0], wr[1], a.res_y};
  const auto t0 = std::chrono::steady_clock::now();
  const RegimeMap m = delta0_omega_map(a.p, b, delta0, omega);
  const double map_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const std::string tag = "delta0-omega_" + bn;
  write_file(dir, "regime_" + tag + ".csv", map_csv(m, "delta0", "omega"));
  files.push_back("regime_" + tag + ".csv");

  // Root-found focusing frequency bands per delta0 (hatched in the figure), band edges, counts.
  std::vector<std::vector<FocusingInterval>> per(delta0.n);
#pragma omp parallel for schedule(dynamic)
  for (int i = 0; i < delta0.n; ++i)
    per[i] = focusing_intervals(with_parameter(a.p, ParameterAxis::delta0, delta0.at(i)), b,
                                {1024, 1e-12});
  std::ostringstream iv, cnt, edges;
  iv.precision(12);
  cnt.precision(12);
  edges.precision(12);
  iv << "delta0,omega_lo,omega_hi,theta_lo,theta_hi,lo_cause,hi_cause,delta0_lo,delta0_hi\n";
  cnt << "delta0,focusing_bands\n";
  edges << "delta0,omega_theta0,omega_thetapi\n";
  json transitions = json::array();
  int prev = -1;
  for (int i = 0; i < delta0.n; ++i) {
    const double d = delta0.at(i);
    const Params p = with_parameter(a.p, ParameterAxis::delta0, d);
    // cell edges in delta0 (for the hatched boxes)
    const double dl = i > 0 ? 0.5 * (delta0.at(i - 1) + d) : d;
    const double dh = i + 1 < delta0.n ? 0.5 * (d + delta0.at(i + 1)) : d;
    for (const auto& f : per[i]) {
      iv << d << ',' << dispersion_omega(p, b, f.lo) << ',' << dispersion_omega(p, b, f.hi) << ','
         << f.lo << ',' << f.hi << ',' << to_string(f.lo_cause) << ',' << to_string(f.hi_cause)
         << ',' << dl << ',' << dh << '\n';
    }
    const int n = static_cast<int>(per[i].size());
    cnt << d << ',' << n << '\n';
    edges << d << ',' << dispersion_omega(p, b, 0.0) << ','
          << dispersion_omega(p, b, std::numbers::pi) << '\n';
    if (n != prev)
      transitions.push_back({{"delta0_from", i > 0 ? json(delta0.at(i - 1)) : json(nullptr)},
                             {"delta0_to", d},
                             {"focusing_bands", n}});
    prev = n;
  }
  write_file(dir, "intervals_" + tag + ".csv", iv.str());
  write_file(dir, "band_count_" + tag + ".csv", cnt.str());
  write_file(dir, "band_edges_" + tag + ".csv", edges.str());
  for (auto f : {"intervals_", "band_count_", "band_edges_"}) files.push_back(f + tag + ".csv");

  std::ostringstream gp;
  gp << "# Focusing (hatched) and defocusing (white) modes of the " << bn
     << " band versus precompression delta0, cf. Figs. 4-5 of the paper.\n"
     << "# Re-run: gnuplot regime_" << tag << ".gp\n"
     << "if (!exists('outfile')) outfile = 'regime_" << tag << ".png'\n"
     << "set terminal pngcairo size 800,900 font 'DejaVu Sans,11'\nset output outfile\n"
     << "set datafile separator ','\n"
     << "set multiplot layout 2,1 margins 0.12,0.96,0.07,0.95 spacing 0,0.12\n"
     << (a.delta0_log ? "set logscale x\n" : "") << "set xrange [" << dr[0] << ":" << dr[1]
     << "]\nset yrange [" << wr[0] << ":" << wr[1] << "]\n"
     << "set xlabel 'δ_0'\nset ylabel 'ω'\n"
     << fmt::format("set title \"{} band, ρ = {:.4g}, κ = {:.4g}, α = {:.4g}: hatched = focusing (ω″h̃ < 0)\"\n", bn,
                    a.p.rho, a.p.kappa, a.p.alpha)
     << "set key top left opaque box font ',9'\n"
     << "plot 'intervals_" << tag
     << ".csv' using 1:(($2+$3)/2):8:9:2:3 with boxxyerror fs pattern 4 noborder lc rgb "
        "'#cc3366' title 'focusing', \\\n"
     << "  'band_edges_" << tag << ".csv' using 1:3 with lines lc rgb '#000000' dt 3 lw 2 title "
     << (b == Branch::optical ? "'ω_+(π)'" : "'ω_{−}(π)'");
  if (b == Branch::optical)
    gp << ", \\\n  'band_edges_" << tag
       << ".csv' using 1:2 with lines lc rgb '#ff0000' lw 2 title 'ω_+(0)'";
  json curves_info = json::object();
  if (!a.no_curves) {
    const auto t1 = std::chrono::steady_clock::now();
    auto curves = boundary_curves(a.p, b, ParameterAxis::delta0, dr[0], dr[1]);
    to_omega_plane(curves, a.p, b);
    curves_info["seconds"] =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t1).count();
    for (BoundaryCause c : kSmoothCauses) {
      int n = 0;
      const std::string csv = curves_csv(curves, c, "delta0", "omega", n);
      curves_info[std::string(to_string(c))] = n;
      if (n == 0) continue;
      const std::string f = "boundary_" + tag + "_" + std::string(to_string(c)) + ".csv";
      write_file(dir, f, csv);
      files.push_back(f);
      gp << ", \\\n  '" << f << "' using 1:2 with lines " << cause_style(c) << " title \""
         << cause_title(c) << "\"";
    }
  }
  gp << "\nset title 'number of focusing frequency bands'\nset ylabel 'bands'\n"
        "set yrange [-0.2:*]\nset ytics 1\nunset key\n"
     << "plot 'band_count_" << tag << ".csv' using 1:2 with steps lw 2 lc rgb '#cc3366'\n"
     << "unset multiplot\n";
  write_file(dir, "regime_" + tag + ".gp", gp.str());
  files.push_back("regime_" + tag + ".gp");
  json out = {{"plane", "delta0-omega"},
              {"branch", bn},
              {"delta0_range", dr},
              {"omega_range", wr},
              {"resolution", {a.res_x, a.res_y}},
              {"map_seconds", map_s},
              {"focusing_band_count", transitions},
              {"boundary_polylines", curves_info}};
  if (!a.no_figures) {
    const bool ok = figures.draw_written("regime_" + tag + ".gp", "regime_" + tag + ".png");
    if (ok) files.push_back(sim::figure_file_name("regime_" + tag + ".png"));
    out["png"] = ok;
  }
  out["files"] = files;
  return out;
}

// ---- regime map of a model file (--model) ---------------------------------------------------

// The axis, its range per branch and the branches of a model's (parameter, theta) map.
struct ModelMapPlan {
  std::string axis;
  std::vector<Index> branches;
  std::vector<std::vector<double>> ranges;  // per branch: lo hi
};

// Default axis range: the resonant chain's rho as in Fig. 2, else the parameter's declared range
// when it is bounded (open ends moved inwards by 1e-3 of its width).
std::vector<double> default_axis_range(const Model& m, const ParameterLine& line, Index branch) {
  if (m.name() == "resonant_chain" && line.parameter().name == "rho")
    return m.definition().branch_names[static_cast<std::size_t>(branch)] == "optical" ? std::vector<double>{0.01, 30.0}
                                                           : std::vector<double>{0.01, 2.5};
  const ModelParameter& p = line.parameter();
  if (!(p.has_lower && p.has_upper))
    throw InvalidParameter("axis-range", "is required for " + p.name + " (its range " + p.range_text +
                                             " is unbounded), e.g. --axis-range 0.5 2");
  const double width = p.upper - p.lower;
  return {p.lower_closed ? p.lower : p.lower + 1e-3 * width, p.upper_closed ? p.upper : p.upper - 1e-3 * width};
}

ModelMapPlan plan_model_map(const MapArgs& a, const Model& m) {
  ModelMapPlan plan;
  plan.axis = !a.axis.empty() ? a.axis : m.name() == "resonant_chain" ? "rho" : m.definition().parameters.at(0).name;
  const ParameterLine line(m, plan.axis);
  if (a.branch == "both" || a.branch == "all") {
    for (auto b = static_cast<Index>(m.definition().branch_names.size()); b-- > 0;) plan.branches.push_back(b);  // optical first
  } else {
    plan.branches.push_back(m.branch(a.branch));
  }
  for (Index b : plan.branches) {
    const auto r = range_or(a.axis_range, {0.0, 1.0}, "axis-range");
    plan.ranges.push_back(a.axis_range.empty() ? default_axis_range(m, line, b) : r);
    line.check_range(plan.ranges.back()[0], plan.ranges.back()[1], "axis-range");
  }
  return plan;
}

// sign(omega'' h_tilde) over (parameter, theta) for each branch of the plan, with the boundary
// curves, a gnuplot script and its PNG (the model-file counterpart of map_theta_rho).
json map_model(const MapArgs& a, const Model& m, const ModelMapPlan& plan, const fs::path& dir,
               sim::Figures& figures) {
  json files = json::array(), panels = json::array();
  const std::string plane = "theta-" + plan.axis;
  std::ostringstream gp;
  gp << "# Regime map sign(omega'' h_tilde) of model " << sim::gnuplot_string(m.name()) << " over (" << plan.axis
     << ", theta).\n# Pink: focusing (omega'' h_tilde < 0), white: defocusing, grey: no frequency. Re-run: gnuplot "
     << "regime_" << plane << ".gp\n"
     << "if (!exists('outfile')) outfile = 'regime_" << plane << ".png'\n"
     << "set terminal pngcairo size " << 700 * plan.branches.size() << ",620 font 'DejaVu Sans,11'\n"
     << "set output outfile\nset datafile separator ','\n" << kPalette
     << "set multiplot\nset xlabel '" << gnuplot_literal(plan.axis) << "'\nset ylabel 'θ'\n"
     << "set key top right opaque box font ',9'\n";
  const double panel_w = 1.0 / static_cast<double>(plan.branches.size());
  for (std::size_t k = 0; k < plan.branches.size(); ++k) {
    const Index b = plan.branches[k];
    const std::string bn = m.definition().branch_names[static_cast<std::size_t>(b)];
    const auto& rr = plan.ranges[k];
    const GridAxis x{rr[0], rr[1], a.res_x}, theta{std::numbers::pi / a.res_y, std::numbers::pi, a.res_y};
    const auto t0 = std::chrono::steady_clock::now();
    const ModelRegimeMap map = parameter_theta_map(m, b, plan.axis, x, theta);
    const double map_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const std::string mapfile = "regime_" + plane + "_" + bn + ".csv";
    RegimeMap pixels{Branch::optical, map.x, map.y, map.values};
    write_file(dir, mapfile, map_csv(pixels, plan.axis.c_str(), "theta"));
    files.push_back(mapfile);
    gp << "set origin " << k * panel_w << ",0\nset size " << panel_w << ",1\n"
       << "set title '" << gnuplot_literal(m.name()) << ", " << gnuplot_literal(bn) << " branch'\n"
       << "set xrange [" << rr[0] << ":" << rr[1] << "]\nset yrange [0:pi]\n";
    std::ostringstream plot;
    plot << "plot '" << mapfile << "' using 1:2:3 with image notitle";
    json curves_info = json::object();
    if (!a.no_curves) {
      const auto t1 = std::chrono::steady_clock::now();
      const auto curves = boundary_curves(m, b, plan.axis, rr[0], rr[1]);
      curves_info["seconds"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - t1).count();
      for (BoundaryCause c : kSmoothCauses) {
        int n = 0;
        const std::string csv = curves_csv(curves, c, plan.axis.c_str(), "theta", n);
        curves_info[std::string(to_string(c))] = n;
        if (n == 0) continue;
        const std::string f = "boundary_" + plane + "_" + bn + "_" + std::string(to_string(c)) + ".csv";
        write_file(dir, f, csv);
        files.push_back(f);
        plot << ", \\\n  '" << f << "' using 1:2 with lines " << cause_style(c) << " title \"" << to_string(c)
             << "\"";
      }
    }
    gp << plot.str() << "\n";
    int focusing = 0;
    for (auto v : map.values) focusing += v == PixelRegime::focusing;
    panels.push_back({{"branch", bn},
                      {"axis_range", rr},
                      {"resolution", {a.res_x, a.res_y}},
                      {"map_seconds", map_s},
                      {"focusing_fraction", double(focusing) / map.values.size()},
                      {"boundary_polylines", curves_info}});
  }
  gp << "unset multiplot\n";
  const std::string script = "regime_" + plane + ".gp";
  write_file(dir, script, gp.str());
  files.push_back(script);
  json out = {{"plane", plane}, {"axis", plan.axis}, {"model", model_json(m)}, {"panels", panels}};
  if (!a.no_figures) {
    const bool ok = figures.draw_written(script, "regime_" + plane + ".png");
    if (ok) files.push_back("regime_" + plane + ".png");
    out["png"] = ok;
  }
  out["files"] = files;
  return out;
}

// Memory, output space and --out of a map, checked before anything is written.
void validate_map_output(const MapArgs& a, double panels) {
  const sim::ResourceEstimate e = sim::estimate_regime_map(double(a.res_x) * double(a.res_y), panels);
  sim::check_memory(e, a.max_memory, "nx", "lower nx and ny");
  std::error_code ec;
  if (fs::exists(a.out, ec) && !fs::is_directory(a.out, ec))
    throw InputError("--out '" + a.out + "' exists and is not a directory");
  sim::check_output_space(e, a.out, "out", "choose another --out or lower nx and ny");
}

// Checks every option of a map, its memory and output size and --out before anything is written.
void validate_map(const MapArgs& a) {
  validate(a.p);
  if (a.plane != "theta-rho" && a.plane != "delta0-omega")
    throw InvalidParameter("plane", "must be 'theta-rho' or 'delta0-omega', got '" + a.plane + "'");
  const auto branches = branches_of(a.branch);
  // The options of the other plane would do nothing.
  if (a.plane == "theta-rho" && (!a.delta0_range.empty() || !a.omega_range.empty() || a.delta0_log))
    throw InputError(std::string(!a.delta0_range.empty() ? "--delta0-range" : !a.omega_range.empty() ? "--omega-range" : "--delta0-log") +
                     " belongs to --plane delta0-omega; the theta-rho plane takes --rho-range");
  if (a.plane == "delta0-omega" && !a.rho_range.empty())
    throw InputError("--rho-range belongs to --plane theta-rho; the delta0-omega plane takes --delta0-range and --omega-range");
  if (a.plane == "theta-rho") {
    for (const double r : range_or(a.rho_range, {0.01, 30.0}, "rho-range")) {
      check_in_range(r, rho_range, "rho-range");  // each end inside rho's range (lrchain/params.hpp)
      validate(with_parameter(a.p, ParameterAxis::rho, r));
    }
  } else {
    const auto dr = range_or(a.delta0_range, {0.001, 1.0}, "delta0-range");
    for (const double d : dr) {
      check_in_range(d, delta0_range, "delta0-range");
      validate(with_parameter(a.p, ParameterAxis::delta0, d));
    }
    validate(GridAxis{dr[0], dr[1], a.res_x, a.delta0_log}, "delta0");
    // Each end in [0, 2 omega_top], omega_top the top of the optical band over the delta0 range.
    double top = 0;
    for (const double d : dr)
      top = std::max(top, frequency_band(with_parameter(a.p, ParameterAxis::delta0, d), Branch::optical).hi);
    for (const double w : range_or(a.omega_range, {0.0, top}, "omega-range"))
      if (!(w >= 0 && w <= max_frequency_over_spectrum_top * top))
        throw InvalidParameter("omega-range", fmt::format("each end must be in [0, {:.6g}] ({:g} times {:.6g}, the "
                                                          "top of the optical band over the delta0 range); got {:g}",
                                                          max_frequency_over_spectrum_top * top,
                                                          max_frequency_over_spectrum_top, top, w));
  }
  validate_map_output(a, double(branches.size()));
}

void run_map(const MapArgs& a);

// A model file's (parameter, theta) map; the resonant chain's delta0-omega plane through Params.
void run_model_map(const MapArgs& a, const Model& m) {
  if (a.plane == "delta0-omega" && m.name() == "resonant_chain") {
    MapArgs resonant = a;
    resonant.p = resonant_params(m);
    resonant.model = {};
    return run_map(resonant);
  }
  if (a.plane != "theta-rho" && a.plane != "theta-parameter")
    throw InvalidParameter("plane", "with --model: 'theta-parameter' (the default; choose the parameter with --axis)" +
                                        std::string(m.name() == "resonant_chain" ? " or 'delta0-omega'" : "") +
                                        ", got '" + a.plane + "'");
  if (!a.rho_range.empty() || !a.delta0_range.empty() || !a.omega_range.empty() || a.delta0_log)
    throw InvalidParameter("axis-range", "with --model the range of the x axis is --axis-range lo hi (no --rho-range, "
                                         "--delta0-range, --omega-range, --delta0-log)");
  const ModelMapPlan plan = plan_model_map(a, m);
  validate_map_output(a, double(plan.branches.size()));
  const fs::path dir(a.out);
  const sim::OutputLock lock(dir);
  const sim::OutputListing earlier = sim::list_output_files(dir);  // files of an earlier run
  sim::Figures figures(dir);
  json out = map_model(a, m, plan, dir, figures);
  out["out"] = fs::absolute(dir).string();
  figures.finish(out);
  sim::record_stale_files(dir, earlier, out);
  out["provenance"] = provenance_json();
  std::cout << out.dump(2) << '\n';
}

void run_map(const MapArgs& a) {
  validate_map(a);
  const fs::path dir(a.out);
  const sim::OutputLock lock(dir);
  const sim::OutputListing earlier = sim::list_output_files(dir);  // files of an earlier run
  sim::Figures figures(dir);
  json out;
  if (a.plane == "theta-rho")
    out = map_theta_rho(a, dir, figures);
  else if (a.plane == "delta0-omega") {
    // one figure per branch (Fig. 4 optical, Fig. 5 acoustic)
    json maps = json::array();
    for (Branch b : branches_of(a.branch)) {
      MapArgs one = a;
      one.branch = std::string(to_string(b));
      maps.push_back(map_delta0_omega(one, dir, figures));
    }
    out = {{"plane", "delta0-omega"}, {"maps", maps}};
  }
  else
    throw InvalidParameter("plane", "must be 'theta-rho' or 'delta0-omega', got '" + a.plane + "'");
  out["out"] = fs::absolute(dir).string();
  out["model"] = model_json(resonant_chain_model(a.p));
  figures.finish(out);
  sim::record_stale_files(dir, earlier, out);
  out["provenance"] = provenance_json();
  std::cout << out.dump(2) << '\n';
}

// `regime map`: a model file's map, or the resonant chain's (with --set as alias of --rho etc.).
void run_map_command(const MapArgs& a, const CLI::App& cmd) {
  if (a.model.file.empty()) validate(a.p);  // the resonant chain's own messages
  if (a.model.file.empty() && (!a.axis.empty() || !a.axis_range.empty()))
    throw InvalidParameter("axis", "--axis and --axis-range need --model FILE (the default map is theta-rho: --rho-range)");
  const Model m = load_selected_model(a.model, cmd, a.p);
  if (!a.model.file.empty()) return run_model_map(a, m);
  MapArgs resonant = a;
  resonant.p = resonant_params(m);
  run_map(resonant);
}

// ---- regime thresholds ----------------------------------------------------------------------

struct ThresholdsArgs {
  int scan = 0;
  bool json_flag = false;
  ModelSelection model;
  std::string branch, axis;
  std::vector<std::string> axis_range;
};

// Structure changes along one parameter of a model file (no paper values to match).
void run_model_thresholds(const ThresholdsArgs& a, const Model& m) {
  MapArgs map_like;
  map_like.branch = a.branch.empty() ? "both" : a.branch;
  map_like.axis = a.axis;
  map_like.axis_range = a.axis_range;
  const ModelMapPlan plan = plan_model_map(map_like, m);
  json scans = json::array();
  for (std::size_t k = 0; k < plan.branches.size(); ++k) {
    const Index b = plan.branches[k];
    const GridAxis scan{plan.ranges[k][0], plan.ranges[k][1], a.scan > 0 ? a.scan : 300};
    const auto t0 = std::chrono::steady_clock::now();
    const auto events = regime_events(m, b, plan.axis, scan);
    const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    json ev = json::array();
    for (const auto& e : events) ev.push_back(event_json(e));
    scans.push_back({{"branch", m.definition().branch_names[static_cast<std::size_t>(b)]},
                     {"axis", plan.axis},
                     {"scan", {{"lo", scan.lo}, {"hi", scan.hi}, {"points", scan.n}}},
                     {"events", ev},
                     {"seconds", secs}});
  }
  std::cout << json{{"model", model_json(m)}, {"scans", scans}, {"provenance", provenance_json()}}.dump(a.json_flag ? -1 : 2) << '\n';
}

void run_thresholds(int scan_points, bool compact) {
  json scenarios = json::array();
  for (auto s : paper_threshold_scenarios()) {
    if (scan_points > 0) s.scan.n = scan_points;
    const auto t0 = std::chrono::steady_clock::now();
    const auto events = regime_events(s.base, s.branch, s.axis, s.scan);
    const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    json ev = json::array(), matched = json::array();
    for (const auto& e : events) ev.push_back(event_json(e));
    for (const auto& m : match_paper_values(s, events)) {
      json j = {{"paper", m.paper}, {"found", m.found}};
      if (m.found) {
        j["computed"] = m.event.value;
        j["relative_difference"] = m.event.value / m.paper - 1.0;
        j["event"] = event_json(m.event);
      }
      matched.push_back(j);
    }
    scenarios.push_back({{"name", s.name},
                         {"branch", std::string(to_string(s.branch))},
                         {"axis", std::string(to_string(s.axis))},
                         {"model", model_json(resonant_chain_model(s.base))},
                         {"scan", {{"lo", s.scan.lo}, {"hi", s.scan.hi}, {"points", s.scan.n}}},
                         {"paper_text", s.paper_text},
                         {"paper_values", matched},
                         {"events", ev},
                         {"seconds", secs}});
  }
  std::cout << json{{"scenarios", scenarios}, {"provenance", provenance_json()}}.dump(compact ? -1 : 2) << '\n';
}

}  // namespace

void register_regime(CLI::App& app) {
  auto* regime = app.add_subcommand(
      "regime",
      "Focusing/defocusing regimes of the NLS limit (Sec. 3.3, Figs. 2, 4, 5): focusing "
      "wavenumber intervals (omega'' h_tilde < 0), regime maps and special parameter values.");
  regime->require_subcommand(1);
  add_examples(*regime, {"lrchain regime intervals --branch optical --rho 1/3",
                         "lrchain regime map --plane theta-rho --branch both --out out/map"});

  // intervals
  auto ia = std::make_shared<IntervalsArgs>();
  auto* in = regime->add_subcommand(
      "intervals",
      "Focusing theta-intervals in (0, pi] for one branch. Ends are found by TOMS 748 on the smooth "
      "functions omega'', numerator of h_tilde, eq:nonresonance1, eq:nonresonance2 to 1e-12 in "
      "theta and labelled curvature_zero, h_tilde_zero, nonresonance1, nonresonance2 or band_edge. "
      "theta is the dimensionless carrier wavenumber (radians per site).");
  add_model_options(*in, ia->p, false);
  add_model_file_options(*in, ia->model);
  in->add_option("--branch", ia->branch,
                 "optical or acoustic (default optical); with --model: the model's branch names (default optical, or "
                 "its only branch)")
      ->type_name("NAME");
  add_integer(*in, "--samples", ia->samples, config::intervals_samples.least, config::intervals_samples.most,
              "theta samples used to bracket the zeros (default 2048)");
  in->add_flag("--json", ia->json_flag, "print the JSON on one line (default: indented)");
  add_examples(*in, {"lrchain regime intervals --branch acoustic --rho 1 --delta0 4/9"});
  in->callback([ia, in] { run_intervals(*ia, *in); });

  // map
  auto ma = std::make_shared<MapArgs>();
  auto* mp = regime->add_subcommand(
      "map",
      "Regime map written to --out: CSV pixel map (regime -1 outside band, 0 defocusing, "
      "1 focusing, 2 singular), boundary curves as CSV polylines per cause (traced by "
      "continuation), a gnuplot script and its PNG. theta-rho: Fig. 2 (rho on x, theta on y; "
      "default rho range 0.01..30 optical, 0.01..2.5 acoustic; branch both draws two panels). "
      "delta0-omega: Figs. 4-5 (kappa as given, paper: 1; default delta0 0.001..1; hatched "
      "focusing frequency bands from root-found intervals, and their number versus delta0). "
      "With --model FILE: the (parameter, theta) plane of any model parameter (--axis NAME, "
      "--axis-range lo hi), files regime_theta-NAME_BRANCH.csv.");
  add_model_options(*mp, ma->p, false);
  add_model_file_options(*mp, ma->model);
  mp->add_option("--axis", ma->axis,
                 "with --model: the parameter on x (default rho for the resonant chain, else the model's first)")
      ->type_name("NAME");
  mp->add_option("--axis-range", ma->axis_range,
                 "with --model: lo hi of the --axis parameter (default: its declared range when bounded)")
      ->expected(2)
      ->type_name("NUM");
  mp->add_option("--plane", ma->plane, "theta-rho (default) or delta0-omega")->type_name("NAME");
  mp->add_option("--branch", ma->branch,
                 "optical, acoustic or both (default both); with --model: a branch name or both/all")
      ->type_name("NAME");
  mp->add_option("--out", ma->out, "output directory (created)")->required()->type_name("DIR");
  mp->add_option("--rho-range", ma->rho_range,
                 "theta-rho: rho lo hi (default 0.01 30 for optical or both, 0.01 2.5 for acoustic)")
      ->expected(2)
      ->type_name("NUM");
  mp->add_option("--delta0-range", ma->delta0_range, "delta0-omega: delta0 lo hi (default 0.001 1)")
      ->expected(2)
      ->type_name("NUM");
  mp->add_option("--omega-range", ma->omega_range,
                 "delta0-omega: omega lo hi, each in [0, twice the top of the optical band] (default: the band over the delta0 range)")
      ->expected(2)
      ->type_name("NUM");
  mp->add_flag("--delta0-log", ma->delta0_log, "delta0-omega: logarithmic delta0 axis (default: linear)");
  add_integer(*mp, "--nx", ma->res_x, config::map_pixels_x.least, config::map_pixels_x.most, "pixels along x (rho or delta0), default 600");
  add_integer(*mp, "--ny", ma->res_y, config::map_pixels_y.least, config::map_pixels_y.most, "pixels along y (theta or omega), default 600");
  add_max_memory(*mp, ma->max_memory);
  add_figure_format(*mp);
  mp->add_flag("--no-curves", ma->no_curves, "skip tracing the boundary curves");
  mp->add_flag("--no-figures", ma->no_figures, "write the data and .gp scripts but draw no figures (no gnuplot run; default: figures)");
  add_examples(*mp, {"lrchain regime map --plane theta-rho --branch both --out out/fig2",
                      "lrchain regime map --plane delta0-omega --branch optical --rho 3 --out out/fig4"});
  mp->callback([ma, mp] { run_map_command(*ma, *mp); });

  // thresholds
  auto ta = std::make_shared<ThresholdsArgs>();
  auto* th = regime->add_subcommand(
      "thresholds",
      "The paper's special mass ratios and precompressions (Sec. 3.3) computed as codimension-two "
      "points: scans of rho (delta0 = 4/9) or delta0 (rho = 3, 17.8, 0.32), kappa = 1, "
      "alpha = 3/2; every change of the boundary structure is located by TOMS 748 (crossing of "
      "two boundary curves, fold = birth/death of a pair of boundaries, entry through theta = pi) "
      "with the number of focusing intervals before and after, and matched to the printed values. "
      "With --model FILE: the same events along one parameter of that model (--axis, --axis-range, --branch).");
  add_integer(*th, "--scan", ta->scan, 10, 100'000,
              "scan points per scenario (default: built-in 300-400; with --model 300)");
  th->add_flag("--json", ta->json_flag, "print the JSON on one line (default: indented)");
  add_model_file_options(*th, ta->model);
  th->add_option("--axis", ta->axis, "with --model: the scanned parameter (default rho / the model's first)")
      ->type_name("NAME");
  th->add_option("--axis-range", ta->axis_range, "with --model: lo hi of the scan (default: its declared range when bounded)")
      ->expected(2)
      ->type_name("NUM");
  th->add_option("--branch", ta->branch, "with --model: a branch name (default: every branch)")->type_name("NAME");
  add_examples(*th, {"lrchain regime thresholds", "lrchain regime thresholds --model fput --axis b --axis-range 0.1 2"});
  th->callback([ta, th] {
    if (ta->model.file.empty()) {
      if (!ta->model.set.empty() || !ta->axis.empty() || !ta->axis_range.empty() || !ta->branch.empty())
        throw InvalidParameter("model", "--set, --axis, --axis-range and --branch need --model FILE (without it "
                                        "the paper's scenarios run)");
      return run_thresholds(ta->scan, ta->json_flag);
    }
    run_model_thresholds(*ta, load_selected_model(ta->model, *th, Params{}));
  });
}

}  // namespace lrchain::cli

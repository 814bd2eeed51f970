// The files of a regime map (regime_job.hpp): pixel maps and boundary polylines as CSV, the gnuplot
// script of each figure (Fig. 2, Figs. 4-5, or a model's (parameter, theta) plane) and its figure.
#include <algorithm>
#include <cstddef>
#include <numbers>
#include <sstream>
#include <string>

#include <fmt/format.h>

#include "lrchain/dispersion.hpp"
#include "lrchain/jobs/regime_hdf5.hpp"
#include "lrchain/jobs/regime_job.hpp"
#include "lrchain/regime/regime_map.hpp"
#include "lrchain/jobs/figure_format.hpp"
#include "lrchain/jobs/gnuplot_text.hpp"
#include "lrchain/jobs/output_files.hpp"

namespace lrchain::jobs {

namespace fs = std::filesystem;
using namespace lrchain::regime;

namespace {

// Pixel map as CSV "x,y,regime" in scan order (y rows, blank line between rows for gnuplot).
std::string map_csv(const GridAxis& x, const GridAxis& y, const std::vector<std::int8_t>& values,
                    const std::string& xname, const std::string& yname) {
  std::ostringstream s;
  s.precision(8);
  s << xname << ',' << yname << ",regime\n";
  for (Index j = 0; j < y.n; ++j) {
    for (Index i = 0; i < x.n; ++i)
      s << x.at(i) << ',' << y.at(j) << ',' << static_cast<int>(values[static_cast<std::size_t>(j * x.n + i)]) << '\n';
    s << '\n';
  }
  return s.str();
}

// Boundary polylines of one cause as CSV "x,y", one blank line between polylines; "" if none.
std::string curves_csv(const std::vector<BoundaryCurve>& curves, BoundaryCause cause, const std::string& xname,
                       const std::string& yname) {
  std::ostringstream s;
  s.precision(15);
  s << xname << ',' << yname << '\n';
  int count = 0;
  for (const auto& c : curves) {
    if (c.cause != cause) continue;
    ++count;
    for (const auto& p : c.points) s << p.x << ',' << p.y << '\n';
    s << '\n';
  }
  return count > 0 ? s.str() : std::string();
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

// The legend's name of a boundary, enhanced text; omega'' as d^2ω/dθ^2 (at 9 pt a double prime
// reads as a tilde). Only the resonant chain's second non-resonance condition has a known formula.
std::string cause_title(BoundaryCause c, bool resonant_chain) {
  switch (c) {
    case BoundaryCause::curvature_zero: return "d^2ω/dθ^2 = 0";
    case BoundaryCause::nonresonance2: return resonant_chain ? "c^2(1+ρ) = K_2 (nonres. 2)" : "nonres. 2 violated";
    case BoundaryCause::nonresonance1: return "nonres. 1 violated";
    case BoundaryCause::h_tilde_zero: return "h̃ = 0";
    case BoundaryCause::band_edge: return "band edge";
  }
  return "";
}

// A title for a single-quoted gnuplot string in enhanced mode, shown literally.
std::string gnuplot_literal(const std::string& text) {
  return jobs::gnuplot_text(text, jobs::GnuplotTextMode::enhanced);
}

// Legend entries for the colours of the pixel map (the palette of kPalette): focusing and
// defocusing always, no frequency and singular where a pixel has them.
std::string regime_key(const std::vector<std::int8_t>& values) {
  const auto has = [&values](int v) { return std::find(values.begin(), values.end(), v) != values.end(); };
  const auto entry = [](const char* colour, const char* title) {
    return fmt::format(", \\\n  keyentry with boxes fillstyle solid 1.0 border lc rgb '#000000' fillcolor rgb '{}' "
                       "title '{}'",
                       colour, title);
  };
  std::string key = entry("#ffaacc", "focusing") + entry("#ffffff", "defocusing");
  if (has(regime::PixelRegime::outside)) key += entry("#dddddd", "no frequency");
  if (has(regime::PixelRegime::singular)) key += entry("#000000", "singular");
  return key;
}

const char* kPalette =
    "set palette defined (-1 '#dddddd', 0 '#ffffff', 1 '#ffaacc', 2 '#000000')\n"
    "set cbrange [-1:2]\nunset colorbox\n";

// The legend below the panels, where it hides no part of the map, in a bottom margin of the same
// height in every panel (so that the panels' frames line up).
const char* kKeyBelow = "set key outside below center horizontal box font ',9' maxrows 3\nset bmargin 8\n";

// Writes the boundary files of one panel ("<prefix>_<cause>.csv") and adds them to `plot`.
void write_curves(const RegimeMapPanel& panel, const fs::path& dir, const std::string& prefix,
                  const std::string& xname, const std::string& yname, bool resonant_chain, std::ostream& plot,
                  std::vector<std::string>& files) {
  if (!panel.curves_traced) return;
  for (BoundaryCause c : kSmoothCauses) {
    const std::string csv = curves_csv(panel.curves, c, xname, yname);
    if (csv.empty()) continue;
    const std::string f = prefix + "_" + std::string(to_string(c)) + ".csv";
    jobs::write_file_atomic(dir, f, csv);
    files.push_back(f);
    plot << ", \\\n  '" << f << "' using 1:2 with lines " << cause_style(c) << " title '"
         << cause_title(c, resonant_chain) << "'";
  }
}

// Draws `script` unless the result says no figures.
std::optional<bool> draw(const RegimeMapResult& r, jobs::Figures& figures, const std::string& script,
                         const std::string& png, std::vector<std::string>& files) {
  if (!r.figures) return std::nullopt;
  const bool ok = figures.draw_written(script, png);
  if (ok) files.push_back(jobs::figure_file_name(png));  // drawn in the --figure-format
  return ok;
}

// Fig. 2: every branch a panel over (rho, theta), the acoustic one with its inset.
void write_theta_rho(const RegimeMapResult& r, const fs::path& dir, jobs::Figures& figures, RegimeMapFiles& out) {
  std::vector<std::string> files;
  std::ostringstream gp;
  const Params& p = r.params;
  gp << "# Regime map sign(omega'' h_tilde) over (rho, theta), cf. Fig. 2 of the paper.\n"
        "# Pink: focusing (omega'' h_tilde < 0), white: defocusing. Re-run: gnuplot "
        "regime_theta-rho.gp\n"
     << "if (!exists('outfile')) outfile = 'regime_theta-rho.png'\n"
     << "set terminal pngcairo size " << 700 * r.panels.size() << ",620 font 'DejaVu Sans,11'\n"
     << "set output outfile\nset datafile separator ','\n" << kPalette
     << "set multiplot\n"
     << "set xlabel 'ρ'\nset ylabel 'θ'\n"
     << kKeyBelow;
  const double panel_w = 1.0 / static_cast<double>(r.panels.size());
  for (std::size_t k = 0; k < r.panels.size(); ++k) {
    const RegimeMapPanel& panel = r.panels[k];
    const std::string& bn = panel.branch;
    const std::string mapfile = "regime_theta-rho_" + bn + ".csv";
    jobs::write_file_atomic(dir, mapfile, map_csv(panel.x, panel.y, panel.values, "rho", "theta"));
    files.push_back(mapfile);
    const bool inset = panel.inset_x.has_value();
    gp << "set origin " << k * panel_w << ",0\nset size " << panel_w << ",1\n"
       << fmt::format("set title '{} branch (α = {:.4g}, δ_0 = {:.4g}, κ = {:.4g})'\n", bn, p.alpha, p.delta0, p.kappa)
       << "set xrange [" << panel.x.lo << ":" << panel.x.hi << "]\nset yrange [0:pi]\n";
    if (inset)
      gp << "set object 1 rect from " << panel.inset_x->lo << "," << panel.inset_y->lo << " to " << panel.inset_x->hi
         << ",pi front fs empty border lc rgb '#000000' lw 1\n";
    std::ostringstream plot;
    plot << "plot '" << mapfile << "' using 1:2:3 with image notitle" << regime_key(panel.values);
    write_curves(panel, dir, "boundary_theta-rho_" + bn, "rho", "theta", true, plot, files);
    gp << plot.str() << "\n";
    if (inset) {
      const std::string zf = "regime_theta-rho_" + bn + "_inset.csv";
      jobs::write_file_atomic(dir, zf, map_csv(*panel.inset_x, *panel.inset_y, panel.inset_values, "rho", "theta"));
      files.push_back(zf);
      std::string zplot = plot.str();
      zplot.replace(zplot.find(mapfile), mapfile.size(), zf);
      gp << "unset object 1\nset origin " << k * panel_w + 0.45 * panel_w << ",0.23\nset size "
         << 0.5 * panel_w << ",0.42\nunset title\nunset xlabel\nunset ylabel\nunset key\nset bmargin -1\n"
         << "set xrange [" << panel.inset_x->lo << ":" << panel.inset_x->hi << "]\nset yrange ["
         << panel.inset_y->lo << ":pi]\n"
         << "set xtics 0.1 font ',8'\nset ytics 0.5 font ',8'\n"
         << zplot << "\n"
         << "set xlabel 'ρ'\nset ylabel 'θ'\nset key\nset bmargin 8\nset xtics auto\n"
            "set ytics auto\n";
    }
  }
  gp << "unset multiplot\n";
  jobs::write_file_atomic(dir, "regime_theta-rho.gp", gp.str());
  files.push_back("regime_theta-rho.gp");
  out.drawn.push_back(draw(r, figures, "regime_theta-rho.gp", "regime_theta-rho.png", files));
  out.files.push_back(std::move(files));
}

// Figs. 4-5: one figure for one branch, the map with the hatched focusing bands over the number of
// focusing bands versus delta0.
void write_delta0_omega(const RegimeMapResult& r, const RegimeMapPanel& panel, const fs::path& dir,
                        jobs::Figures& figures, RegimeMapFiles& out) {
  std::vector<std::string> files;
  const std::string& bn = panel.branch;
  const Branch b = panel.resonant_branch;
  const GridAxis& delta0 = panel.x;
  const std::string tag = "delta0-omega_" + bn;
  jobs::write_file_atomic(dir, "regime_" + tag + ".csv", map_csv(panel.x, panel.y, panel.values, "delta0", "omega"));
  files.push_back("regime_" + tag + ".csv");

  std::ostringstream iv, cnt, edges;
  iv.precision(12);
  cnt.precision(12);
  edges.precision(12);
  iv << "delta0,omega_lo,omega_hi,theta_lo,theta_hi,lo_cause,hi_cause,delta0_lo,delta0_hi\n";
  cnt << "delta0,focusing_bands\n";
  edges << "delta0,omega_theta0,omega_thetapi\n";
  for (Index i = 0; i < delta0.n && std::size_t(i) < panel.bands.size(); ++i) {
    const double d = delta0.at(i);
    // cell edges in delta0 (for the hatched boxes)
    const double dl = i > 0 ? 0.5 * (delta0.at(i - 1) + d) : d;
    const double dh = i + 1 < delta0.n ? 0.5 * (d + delta0.at(i + 1)) : d;
    for (const auto& f : panel.bands[i])
      iv << d << ',' << f.omega_lo << ',' << f.omega_hi << ',' << f.theta.lo << ',' << f.theta.hi << ','
         << to_string(f.theta.lo_cause) << ',' << to_string(f.theta.hi_cause) << ',' << dl << ',' << dh << '\n';
    cnt << d << ',' << panel.bands[i].size() << '\n';
    edges << d << ',' << panel.band_edges[i][0] << ',' << panel.band_edges[i][1] << '\n';
  }
  jobs::write_file_atomic(dir, "intervals_" + tag + ".csv", iv.str());
  jobs::write_file_atomic(dir, "band_count_" + tag + ".csv", cnt.str());
  jobs::write_file_atomic(dir, "band_edges_" + tag + ".csv", edges.str());
  for (auto f : {"intervals_", "band_count_", "band_edges_"}) files.push_back(f + tag + ".csv");

  const Params& p = r.params;
  std::ostringstream gp;
  gp << "# Focusing (hatched) and defocusing (white) modes of the " << bn
     << " band versus precompression delta0, cf. Figs. 4-5 of the paper.\n"
     << "# Re-run: gnuplot regime_" << tag << ".gp\n"
     << "if (!exists('outfile')) outfile = 'regime_" << tag << ".png'\n"
     << "set terminal pngcairo size 1000,900 font 'DejaVu Sans,11'\nset output outfile\n"
     << "set datafile separator ','\n"
     << "set multiplot layout 2,1 margins 0.09,0.71,0.07,0.95 spacing 0,0.12\n"
     << (r.delta0_log ? "set logscale x\n" : "") << "set xrange [" << panel.x.lo << ":" << panel.x.hi
     << "]\nset yrange [" << panel.y.lo << ":" << panel.y.hi << "]\n"
     << "set xlabel 'δ_0'\nset ylabel 'ω'\n"
     << fmt::format("set title \"{} band, ρ = {:.4g}, κ = {:.4g}, α = {:.4g}: hatched = focusing (h̃ d^2ω/dθ^2 < 0)\"\n", bn,
                    p.rho, p.kappa, p.alpha)
     << "# the legend beside the map, where it hides none of it\nset key outside right top box font ',9'\n"
     << "plot 'intervals_" << tag
     << ".csv' using 1:(($2+$3)/2):8:9:2:3 with boxxyerror fs pattern 4 noborder lc rgb "
        "'#cc3366' title 'focusing', \\\n"
     << "  'band_edges_" << tag << ".csv' using 1:3 with lines lc rgb '#000000' dt 3 lw 2 title "
     << (b == Branch::optical ? "'ω_+(π)'" : "'ω_{−}(π)'");
  if (b == Branch::optical)
    gp << ", \\\n  'band_edges_" << tag << ".csv' using 1:2 with lines lc rgb '#ff0000' lw 2 title 'ω_+(0)'";
  write_curves(panel, dir, "boundary_" + tag, "delta0", "omega", true, gp, files);
  gp << "\nset title 'number of focusing frequency bands'\nset ylabel 'bands'\n"
        "set yrange [-0.2:*]\nset offsets 0, 0, 0.4, 0\nset ytics 1\nunset key\n"
     << "plot 'band_count_" << tag << ".csv' using 1:2 with steps lw 2 lc rgb '#cc3366'\n"
     << "unset multiplot\n";
  jobs::write_file_atomic(dir, "regime_" + tag + ".gp", gp.str());
  files.push_back("regime_" + tag + ".gp");
  out.drawn.push_back(draw(r, figures, "regime_" + tag + ".gp", "regime_" + tag + ".png", files));
  out.files.push_back(std::move(files));
}

// A model's (parameter, theta) plane: every branch a panel (the counterpart of Fig. 2).
void write_model(const RegimeMapResult& r, const fs::path& dir, jobs::Figures& figures, RegimeMapFiles& out) {
  std::vector<std::string> files;
  const std::string& plane = r.plane;
  std::ostringstream gp;
  gp << "# Regime map sign(omega'' h_tilde) of model " << jobs::gnuplot_string(r.model_name) << " over (" << r.axis
     << ", theta).\n# Pink: focusing (omega'' h_tilde < 0), white: defocusing, grey: no frequency. Re-run: gnuplot "
     << "regime_" << plane << ".gp\n"
     << "if (!exists('outfile')) outfile = 'regime_" << plane << ".png'\n"
     << "set terminal pngcairo size " << 700 * r.panels.size() << ",620 font 'DejaVu Sans,11'\n"
     << "set output outfile\nset datafile separator ','\n" << kPalette
     << "set multiplot\nset xlabel '" << gnuplot_literal(r.axis) << "'\nset ylabel 'θ'\n"
     << kKeyBelow;
  const double panel_w = 1.0 / static_cast<double>(r.panels.size());
  for (std::size_t k = 0; k < r.panels.size(); ++k) {
    const RegimeMapPanel& panel = r.panels[k];
    const std::string& bn = panel.branch;
    const std::string mapfile = "regime_" + plane + "_" + bn + ".csv";
    jobs::write_file_atomic(dir, mapfile, map_csv(panel.x, panel.y, panel.values, r.axis, "theta"));
    files.push_back(mapfile);
    gp << "set origin " << k * panel_w << ",0\nset size " << panel_w << ",1\n"
       << "set title '" << gnuplot_literal(r.model_name) << ", " << gnuplot_literal(bn) << " branch'\n"
       << "set xrange [" << panel.x.lo << ":" << panel.x.hi << "]\nset yrange [0:pi]\n";
    std::ostringstream plot;
    plot << "plot '" << mapfile << "' using 1:2:3 with image notitle" << regime_key(panel.values);
    write_curves(panel, dir, "boundary_" + plane + "_" + bn, r.axis, "theta", false, plot, files);
    gp << plot.str() << "\n";
  }
  gp << "unset multiplot\n";
  const std::string script = "regime_" + plane + ".gp";
  jobs::write_file_atomic(dir, script, gp.str());
  files.push_back(script);
  out.drawn.push_back(draw(r, figures, script, "regime_" + plane + ".png", files));
  out.files.push_back(std::move(files));
}

}  // namespace

RegimeMapFiles write(const RegimeMapResult& r, const fs::path& dir, jobs::Figures& figures) {
  RegimeMapFiles out;
  if (!r.resonant_chain)
    write_model(r, dir, figures, out);
  else if (r.plane == "theta-rho")
    write_theta_rho(r, dir, figures, out);
  else
    for (const RegimeMapPanel& panel : r.panels) write_delta0_omega(r, panel, dir, figures, out);
  if (r.format == "hdf5") out.hdf5 = write_hdf5(r, dir);
  return out;
}

}  // namespace lrchain::jobs

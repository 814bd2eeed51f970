// The figures lrchain draws, checked in their gnuplot scripts and file lists without looking at
// them: text from a model shown as written (no underscore read as a subscript), the drawn files
// named in the figure format, markers and ranges that show the data as they are.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <filesystem>
#include <iterator>
#include <memory>
#include <numbers>
#include <string>

#include "../support/gnuplot_script_checks.hpp"
#include "../support/scratch_dir.hpp"
#include "sweep_test_files.hpp"
#include "lrchain/jobs/dark_job.hpp"
#include "lrchain/jobs/regime_job.hpp"
#include "lrchain/jobs/simulate/bright_outputs.hpp"
#include "lrchain/jobs/sweep/sweep_config.hpp"
#include "lrchain/jobs/sweep/sweep_figure.hpp"
#include "lrchain/jobs/simulate/model_bright_outputs.hpp"
#include "lrchain/model.hpp"
#include "lrchain/process.hpp"
#include "lrchain/jobs/figure_format.hpp"
#include "lrchain/sim/bright_run.hpp"
#include "lrchain/sim/model_lattice.hpp"
#include "lrchain/sim/model_lattice_bloch.hpp"
#include "lrchain/jobs/output_files.hpp"

namespace fs = std::filesystem;
using namespace lrchain;
using namespace lrchain::jobs;
using lrchain::test::file_text;
using lrchain::test::multiplot_panels;
using lrchain::test::panels_overlap;
using lrchain::test::scratch_directory;
using lrchain::test::unescaped_underscores_in_text;

namespace {

// A small regime map of the shipped Klein-Gordon model over its parameter b, with its boundary
// curves (omega'' = 0 crosses the band at theta = pi/2).
RegimeMapResult klein_gordon_map(bool figures) {
  RegimeMapConfig c;
  c.lattice.model = std::make_shared<const Model>(shipped_model("klein_gordon", {{"C", 0.5}}));
  c.axis = std::string("b");  // a move (GCC 12 warns falsely on assigning a literal here)
  c.axis_range = Range{-1.0, 1.0};
  c.nx = 24;
  c.ny = 24;
  c.figures = figures;
  return run(c);
}

}  // namespace

TEST_CASE("figure scripts: a model's regime map shows its name and boundary names as written") {
  const fs::path dir = scratch_directory("figure-regime-model");
  const RegimeMapResult r = klein_gordon_map(false);
  jobs::Figures figures(dir);
  const RegimeMapFiles files = write(r, dir, figures);
  const std::string script = file_text(dir / "regime_theta-b.gp");
  REQUIRE(script.find("boundary_theta-b_branch0_curvature_zero.csv") != std::string::npos);  // a boundary is drawn
  CHECK(script.find("klein\\_gordon") != std::string::npos);
  CHECK(unescaped_underscores_in_text(script) == std::vector<std::string>{});
  // The legend names the colours of the map.
  CHECK(script.find("title 'focusing'") != std::string::npos);
  CHECK(script.find("title 'defocusing'") != std::string::npos);
  fs::remove_all(dir);
}

TEST_CASE("figure scripts: a model's regime map drawn as SVG lists the SVG file") {
  const fs::path dir = scratch_directory("figure-regime-svg");
  jobs::set_figure_format(jobs::FigureFormat::svg);
  const RegimeMapResult r = klein_gordon_map(true);
  jobs::Figures figures(dir);
  const RegimeMapFiles files = write(r, dir, figures);
  jobs::set_figure_format(jobs::FigureFormat::png);
  REQUIRE(files.drawn.size() == 1);
  REQUIRE(files.drawn[0] == std::optional<bool>(true));  // gnuplot drew it
  const auto& listed = files.files[0];
  CHECK(std::find(listed.begin(), listed.end(), "regime_theta-b.svg") != listed.end());
  CHECK(std::find(listed.begin(), listed.end(), "regime_theta-b.png") == listed.end());
  for (const auto& f : listed) CHECK(fs::is_regular_file(dir / f));
  fs::remove_all(dir);
}

TEST_CASE("figure scripts: errors.png of a model bright run marks the ansatz at every site") {
  // fput at theta = pi/4: a carrier of 8 sites' period. Markers at every second site sat off the
  // crests (cos(pi/4) = 0.71 of them), 30 % below the lattice curve where the data agree to 1 %.
  const fs::path dir = scratch_directory("figure-model-bright");
  const Model model = shipped_model("fput");
  sim::ModelBrightConfig c;
  c.branch = model.branch("acoustic");
  c.theta = std::numbers::pi / 4;
  c.N = 40;
  c.periods = 1;
  const sim::ModelBrightResult r = sim::run_bright(model, sim::lattice_kernels_of(model), c);
  write_model_bright_outputs(dir, r, nlohmann::json::object(), true);  // the scripts come with the figures
  const std::string script = file_text(dir / "errors.gp");
  const std::size_t ansatz = script.find("using 1:3 skip 1 with points");
  REQUIRE(ansatz != std::string::npos);
  CHECK(script.find("every") == std::string::npos);  // no data point left out
  CHECK(fs::is_regular_file(dir / "errors.png"));     // gnuplot ran the script (its stats of the profile)
  fs::remove_all(dir);
}

TEST_CASE("figure scripts: a model's dark branch above its edge is drawn, named by its own branch") {
  // klein_gordon (b = 1/2): h_tilde > 0 at its theta = 0 edge omega = 1, so the breathers lie above
  // the edge. The x range reached from the lowest point (or the edge) to the edge only: every point
  // fell outside the frame and gnuplot drew nothing.
  const fs::path dir = scratch_directory("figure-dark-branch");
  const Model model = shipped_model("klein_gordon");
  jobs::dark::DarkConfig c;
  c.step = jobs::dark::DarkStep::branch;
  c.model = &model;
  c.kernels = sim::shipped_lattice_kernels("klein_gordon");
  c.omega_b = 1.02;  // far enough above the edge that 40 sites hold a dark breather (1.002 is refused)
  c.sites = 40;
  c.points = 3;
  c.branch_floquet = false;
  c.out = dir.string();
  const jobs::dark::DarkResult r = jobs::dark::run(c);
  REQUIRE(r.branch.points.size() == 3);
  REQUIRE(r.edge.omega < c.omega_b);
  const nlohmann::json j = jobs::dark::write(r, dir);
  CHECK(fs::is_regular_file(dir / "branch.png"));
  const std::string script = file_text(dir / "branch.gp");
  CHECK(script.find("branch0 bond-centred") != std::string::npos);
  CHECK(script.find("optical") == std::string::npos);
  CHECK(script.find("eq. (51)") == std::string::npos);  // the resonant chain's equation
  // The model's name as written, through gnuplot_text (no underscore read as a subscript).
  CHECK(script.find("klein\\_gordon") != std::string::npos);
  CHECK(script.find("klein_gordon") == std::string::npos);
  // floquet_moduli.png over the branch's own omega_b (a branch that moved by only 1e-6 printed every
  // tic as 1.002000 with gnuplot's default): tics with the decimals that tell them apart.
  const std::string moduli = file_text(dir / "floquet_moduli.gp");
  double lo = 0, hi = 0;
  int decimals = -1;
  const std::size_t range = moduli.find("set xrange [");
  REQUIRE(range != std::string::npos);
  REQUIRE(std::sscanf(moduli.c_str() + range, "set xrange [%lf:%lf]", &lo, &hi) == 2);
  const std::size_t format = moduli.find("set format x '%.");
  REQUIRE(format != std::string::npos);
  REQUIRE(std::sscanf(moduli.c_str() + format, "set format x '%%.%df'", &decimals) == 1);
  CHECK(lo <= r.branch.points.front().omega_b);
  CHECK(hi >= r.branch.points.back().omega_b);
  CHECK(lo > r.edge.omega);                         // the branch's own range, not down to the edge
  CHECK(std::pow(10.0, -decimals) <= (hi - lo) / 10);  // a tic step of a tenth of the range shows
  fs::remove_all(dir);
}

TEST_CASE("figure scripts: snapshots.png of a long bright run shows the early errors beside E_x, E_y, not over them") {
  // The paper chain's optical breather at theta = pi/2 (exp1) for 150 T_b = 433 > 400: the run
  // that gets the t <= 200 panel. An inset over the E_x, E_y panel hid E_x for t = 300-530 in exp1.
  const fs::path dir = scratch_directory("figure-bright-snapshots");
  sim::BrightRunConfig c;
  c.branch = Branch::optical;
  c.theta = std::numbers::pi / 2;
  c.N = 100;
  c.periods = 150;
  c.snapshot_periods = {0, 150};
  const sim::BrightRunResult r = sim::run_resonant_chain_bright(c);
  write_bright_outputs(dir, r, nlohmann::json::object(), true);
  const std::string script = file_text(dir / "snapshots.gp");
  REQUIRE(script.find("t ≤ 200") != std::string::npos);  // the early errors are drawn
  const auto panels = multiplot_panels(script);
  REQUIRE(panels.size() == 4);  // x_n, y_n, E_x and E_y, the early E_x and E_y
  for (std::size_t a = 0; a < panels.size(); ++a)
    for (std::size_t b = a + 1; b < panels.size(); ++b) {
      INFO("panels " << a << " and " << b);
      CHECK(!panels_overlap(panels[a], panels[b]));
    }
  CHECK(fs::is_regular_file(dir / "snapshots.png"));
  // energy.png: the energy centre X(t) autoscaled with room above and below (the space-time
  // panel's `set autoscale fix` put both ends of X(t) on the frame's corners).
  const std::string energy = file_text(dir / "energy.gp");
  const std::size_t centre = energy.find("set lmargin at screen 0.57");
  REQUIRE(centre != std::string::npos);
  CHECK(energy.find("set autoscale y\n", centre) != std::string::npos);
  CHECK(energy.find("set offsets 0, 0, graph 0.05, graph 0.05\n", centre) != std::string::npos);
  fs::remove_all(dir);
}

namespace {

// The figure of a 3 x 2 grid sweep of max_Ex over (`x_axis`, detuning) with made-up values
// (log10 = point index - 3, NaN at point 3), written into `dir`; returns its script.
std::string sweep_figure_script(const fs::path& dir, const std::string& x_axis, const std::string& x_values) {
  lrchain::test::write_text(dir / "base.toml", lrchain::test::short_bright_base);
  lrchain::test::write_text(dir / "s.toml", "job = \"bright\"\nname = \"figure\"\nbase = \"base.toml\"\noutput = \"" +
                                                (dir / "s.h5").string() + "\"\nfigure = \"max_Ex\"\n[[axis]]\nparameter = \"" +
                                                x_axis + "\"\nvalues = " + x_values +
                                                "\n[[axis]]\nparameter = \"bright.detuning\"\nvalues = [-1e-4, -1e-2]\n");
  const jobs::sweep::SweepConfig c = jobs::sweep::load_sweep_config(dir / "s.toml");
  const jobs::sweep::Job job = jobs::sweep::make_job(c);
  jobs::sweep::SweepResults r(job, 6);
  const auto& names = r.scalar_names;
  const std::size_t s = std::size_t(std::find(names.begin(), names.end(), "max_Ex") - names.begin());
  for (std::size_t p = 0; p < 6; ++p) r.scalars[s * 6 + p] = p == 3 ? std::nan("") : std::pow(10.0, double(p) - 3);
  jobs::sweep::write_sweep_figures(c, job, r, "max_Ex");
  return file_text(dir / "s_max_Ex.gp");
}

}  // namespace

TEST_CASE("figure scripts: the sweep heat map draws each point as a cell of its own colour around it") {
  // pm3d coloured each quadrangle from its corners: cells shifted by half a step, the last row and
  // column gone, and every quadrangle next to a NaN dropped. Here gnuplot tabulates what the script
  // draws, box by box: each box must hold its own point and its own value.
  if (!lrchain::program_in_path("gnuplot")) return;
  const fs::path dir = scratch_directory("figure-sweep-cells");
  std::string script = sweep_figure_script(dir, "bright.theta", "[1.2, 1.4, 1.8]");
  CHECK(script.find("pm3d") == std::string::npos);
  CHECK(script.find("dashed: focusing interval ends") != std::string::npos);  // 1.8916 is inside the last cell
  CHECK(script.find("set arrow from 1.89") != std::string::npos);
  const std::string style = " with boxxyerror fillstyle solid 1.0 noborder fillcolor palette notitle";
  const std::size_t at = script.find(style);
  REQUIRE(at != std::string::npos);
  script.replace(at, style.size(), " with table");
  script.replace(script.find("\nplot "), 6, "\nset table 'cells.txt'\nplot ");
  lrchain::test::write_text(dir / "cells.gp", script);
  lrchain::ProcessOptions o;
  o.working_directory = dir;
  REQUIRE(lrchain::run_program({"gnuplot", "cells.gp"}, o).ok());
  std::istringstream cells(file_text(dir / "cells.txt"));
  const double theta[] = {1.2, 1.4, 1.8}, detuning[] = {1e-4, 1e-2};
  int boxes = 0, missing = 0;
  for (std::string line; std::getline(cells, line);) {
    double x, y, xlo, xhi, ylo, yhi, z;
    if (std::sscanf(line.c_str(), "%lf %lf %lf %lf %lf %lf %lf", &x, &y, &xlo, &xhi, &ylo, &yhi, &z) != 7) continue;
    const int i = int(std::min_element(std::begin(theta), std::end(theta),
                                       [x](double a, double b) { return std::abs(a - x) < std::abs(b - x); }) -
                      std::begin(theta));
    const int j = y < 1e-3 ? 0 : 1;
    INFO("point " << x << ", " << y);
    CHECK(x == doctest::Approx(theta[i]));
    CHECK(y == doctest::Approx(detuning[j]));
    CHECK(xlo < x);
    CHECK(x < xhi);
    CHECK(ylo < y);
    CHECK(y < yhi);
    if (std::isnan(z)) {  // no value: gnuplot leaves the box out
      CHECK(i * 2 + j == 3);
      ++missing;
      continue;
    }
    CHECK(z == doctest::Approx(double(i * 2 + j) - 3));  // its own value (point index i * 2 + j)
    ++boxes;
  }
  CHECK(boxes == 5);
  CHECK(missing == 1);
  fs::remove_all(dir);
}

TEST_CASE("figure scripts: the sweep heat map promises dashed focusing ends only where it draws them") {
  const fs::path dir = scratch_directory("figure-sweep-title");
  const std::string script = sweep_figure_script(dir, "bright.n0", "[-10, 0, 10]");
  CHECK(script.find("dashed") == std::string::npos);
  CHECK(script.find("set arrow") == std::string::npos);
  fs::remove_all(dir);
}

TEST_CASE("figure scripts: the dark stability atlas marks the band edge at each axis value, not as a line between them") {
  // omega(pi) is known at the swept values only; a line between two of them drew values no run had.
  const fs::path dir = scratch_directory("figure-sweep-stability");
  jobs::sweep::SweepConfig c;
  c.name = "x'; system('touch PWNED'); print '";  // a hostile name: shown, never run
  c.job = "dark continue";
  c.axes = {{"model.rho", {0.5, 2.0}}};
  c.output = dir / "atlas.h5";
  c.figure = "stability";
  jobs::sweep::SweepResults r({"first_turning_point", "omega_edge"}, 2, {"omega_b", "stability", "part"});
  r.scalars = {2.2, 2.15, 2.35, 2.26};  // turning points, then band edges
  r.rows = {{2.34, 0, 0, 2.3, 1, 1}, {2.25, 2, 0, 2.2, 1, 1}};
  jobs::sweep::write_stability_figure(c, r);
  const std::string script = file_text(dir / "atlas_stability.gp");
  const std::size_t edge = script.find("title 'band edge omega(pi)'");
  REQUIRE(edge != std::string::npos);
  const std::string plot = script.substr(script.rfind("using 1:3", edge), edge - script.rfind("using 1:3", edge));
  CHECK(plot.find("with points") != std::string::npos);
  CHECK(plot.find("with lines") == std::string::npos);
  CHECK(script.find("set xtics (0.5, 2)") != std::string::npos);  // the swept values named on the log axis
  const std::string apostrophe = "\xE2\x80\x99";                  // a quote as shown (gnuplot_text.hpp)
  CHECK(script.find("set title 'x" + apostrophe + "; system(" + apostrophe + "touch PWNED" + apostrophe + "); print " +
                    apostrophe + ": dark-breather branches") != std::string::npos);
  if (lrchain::program_in_path("gnuplot")) CHECK(fs::is_regular_file(dir / "atlas_stability.png"));  // drawn all the same
  CHECK(!fs::exists(dir / "PWNED"));
  CHECK(!fs::exists("PWNED"));
  fs::remove_all(dir);
}

TEST_CASE("figure scripts: the fate atlas marks dark stages (o) and bright stages (triangles) at their own points") {
  // Made-up scalars on a 2 x 2 grid: a dark stage at point 1 only, a bright stage at point 2 only.
  const fs::path dir = scratch_directory("figure-fate-stages");
  lrchain::test::write_text(dir / "base.toml", "experiment = \"wave fate\"\nmodel = \"fput\"\n[wave]\ntheta = 2.5\n"
                                               "amplitude = 0.1\nring_sites = 128\n");
  lrchain::test::write_text(dir / "s.toml", "job = \"wave fate\"\nname = \"fate\"\nbase = \"base.toml\"\noutput = \"" +
                                                (dir / "s.h5").string() + "\"\nfigure = \"fate\"\n[[axis]]\n"
                                                "parameter = \"wave.theta\"\nvalues = [1.0, 2.0]\n[[axis]]\n"
                                                "parameter = \"wave.amplitude\"\nvalues = [0.05, 0.1]\n");
  const jobs::sweep::SweepConfig c = jobs::sweep::load_sweep_config(dir / "s.toml");
  const jobs::sweep::Job job = jobs::sweep::make_job(c);
  jobs::sweep::SweepResults r(job, 4);
  const auto column = [&](const std::string& name) {
    const auto at = std::find(r.scalar_names.begin(), r.scalar_names.end(), name);
    REQUIRE(at != r.scalar_names.end());
    return std::size_t(at - r.scalar_names.begin());
  };
  for (std::size_t p = 0; p < 4; ++p) {
    r.scalars[column("fate") * 4 + p] = double(p);
    r.scalars[column("focusing") * 4 + p] = p < 2 ? 0 : 1;  // theta = 1 defocusing, 2 focusing
    r.scalars[column("stable") * 4 + p] = p == 0 ? 1 : 0;   // growth everywhere but (1, 0.05)
    r.scalars[column("dark_from") * 4 + p] = p == 1 ? 100.0 : std::nan("");
    r.scalars[column("bright_from") * 4 + p] = p == 2 ? 200.0 : std::nan("");
  }
  jobs::sweep::write_sweep_figures(c, job, r, "fate");
  std::istringstream data(file_text(dir / "s_fate.dat"));
  int rows = 0;
  for (std::string line; std::getline(data, line);) {
    double x, y, fate, focusing, stable, dark, bright;
    if (std::sscanf(line.c_str(), "%lf %lf %lf %lf %lf %lf %lf", &x, &y, &fate, &focusing, &stable, &dark, &bright) != 7) continue;
    INFO(line);
    CHECK(dark == (fate == 1 ? 1 : 0));
    CHECK(bright == (fate == 2 ? 1 : 0));
    ++rows;
  }
  CHECK(rows == 4);
  const std::string script = file_text(dir / "s_fate.gp");
  CHECK(script.find("'' using 1:($6 > 0 ? $2 : NaN) with points pointtype 6") != std::string::npos);
  CHECK(script.find("'' using 1:($7 > 0 ? $2 : NaN) with points pointtype 8") != std::string::npos);
  CHECK(script.find("triangle bright stage") != std::string::npos);
  // Borders on the cells' shared edges (theta cells split at 1.5, amplitude cells at 0.075 on this linear
  // axis, from 0.025 to 0.125): the NLS's between the two theta columns (two dashed segments), the exact
  // growth's around the one stable cell (theta 1, A 0.05: one vertical and one horizontal segment).
  const auto count = [&](const std::string& text) {
    int n = 0;
    for (std::size_t at = script.find(text); at != std::string::npos; at = script.find(text, at + 1)) ++n;
    return n;
  };
  CHECK(count("set arrow from 1.5, 0.025000000000000001 to 1.5, 0.075000000000000011 nohead") == 2);
  CHECK(count("set arrow from 1.5, 0.075000000000000011 to 1.5, 0.125 nohead dashtype 2") == 1);
  CHECK(count("set arrow from 0.5, 0.075000000000000011 to 1.5, 0.075000000000000011 nohead linewidth 3") == 1);
  CHECK(count("nohead dashtype 2 linewidth 3 lc rgb 'black' front") == 2);
  CHECK(count("nohead linewidth 3 lc rgb '#2166ac' front") == 2);
  fs::remove_all(dir);
}

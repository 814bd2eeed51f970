// `lrchain regime intervals|map|thresholds`: focusing/defocusing regimes of the NLS limit
// (Sec. 3.3, Figs. 2, 4, 5), an argv adapter onto the regime jobs (lrchain/jobs/regime_job.hpp).
// JSON summary on stdout; data, gnuplot scripts and figures in --out.
#include <algorithm>
#include <fmt/format.h>
#include <filesystem>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "commands.hpp"
#include "figure_format_option.hpp"
#include "help_text.hpp"
#include "lrchain/config/option_caps.hpp"
#include "lrchain/errors.hpp"
#include "lrchain/jobs/regime_hdf5.hpp"
#include "lrchain/jobs/regime_job.hpp"
#include "lrchain/jobs/regime_schema.hpp"
#include "lrchain/provenance_json.hpp"
#include "lrchain/jobs/output_files.hpp"
#include "lrchain/jobs/output_lock.hpp"
#include "model_option.hpp"
#include "options.hpp"
#include "schema_help.hpp"

namespace lrchain::cli {

namespace {

using nlohmann::json;
namespace fs = std::filesystem;

// The lattice of a regime job: a --model file, or the resonant chain at --rho etc. (and --set).
jobs::RegimeLattice lattice_of(const ModelSelection& selection, const Model& m) {
  if (!selection.file.empty()) return {Params{}, std::make_shared<const Model>(m)};
  return jobs::resonant_chain_lattice(m);
}

// lo hi of a range option; none when not given.
std::optional<jobs::Range> range_option(const std::vector<std::string>& given, const char* name) {
  if (given.empty()) return std::nullopt;
  if (given.size() != 2) throw InvalidParameter(name, "range needs two numbers lo hi");
  return jobs::Range{parse_number(given[0], name), parse_number(given[1], name)};
}

// "lo<sep>hi" of a default range for a help text.
std::string range_text(const jobs::Range& r, const char* sep) { return fmt::format("{:g}{}{:g}", r[0], sep, r[1]); }

// ---- regime intervals -----------------------------------------------------------------------

struct IntervalsArgs {
  Params p;
  ModelSelection model;
  std::string branch;  // empty: optical (or a model's only branch)
  int samples = jobs::RegimeIntervalsConfig{}.samples;
  bool json_flag = false;
  std::string out;  // --out DIR: also result.h5
};

void run_intervals(const IntervalsArgs& a, const CLI::App& cmd) {
  if (a.model.file.empty()) validate(a.p);  // the resonant chain's own messages
  const Model model = load_selected_model(a.model, cmd, a.p);
  jobs::RegimeIntervalsConfig c;
  c.lattice = lattice_of(a.model, model);
  c.branch = a.branch;
  c.samples = a.samples;
  const jobs::RegimeIntervalsResult result =
      with_option_names(jobs::regime_intervals_options(), [&] { return jobs::run(c); });
  if (!a.out.empty()) jobs::write_hdf5(result, a.out);
  json out = jobs::to_json(result);
  out["provenance"] = provenance_json();
  std::cout << out.dump(a.json_flag ? -1 : 2) << '\n';
}

// ---- regime map -----------------------------------------------------------------------------

struct MapArgs {
  Params p;
  ModelSelection model;
  std::string axis;                     // --model: the parameter on x
  std::vector<std::string> axis_range;  // --model: lo hi
  std::string plane = jobs::RegimeMapConfig{}.plane;
  std::string branch = jobs::RegimeMapConfig{}.branch;
  std::string out;
  std::vector<std::string> rho_range, delta0_range, omega_range;  // lo hi
  int res_x = jobs::RegimeMapConfig{}.nx, res_y = jobs::RegimeMapConfig{}.ny;
  double max_memory = 0;  // bytes (--max-memory); 0: the machine's available memory
  bool delta0_log = false;
  bool no_curves = false;
  bool no_figures = false;
  std::string format = jobs::RegimeMapConfig{}.format;
};

// The options of the other resonant-chain plane would do nothing.
void refuse_other_plane_options(const MapArgs& a) {
  if (a.plane == "theta-rho" && (!a.delta0_range.empty() || !a.omega_range.empty() || a.delta0_log))
    throw InputError(std::string(!a.delta0_range.empty() ? "--delta0-range" : !a.omega_range.empty() ? "--omega-range" : "--delta0-log") +
                     " belongs to --plane delta0-omega; the theta-rho plane takes --rho-range");
  if (a.plane == "delta0-omega" && !a.rho_range.empty())
    throw InputError("--rho-range belongs to --plane theta-rho; the delta0-omega plane takes --delta0-range and --omega-range");
}

// `regime map`: a model file's map, or the resonant chain's (with --set as alias of --rho etc.).
void run_map(const MapArgs& a, const CLI::App& cmd) {
  if (a.model.file.empty()) validate(a.p);  // the resonant chain's own messages
  if (a.model.file.empty() && (!a.axis.empty() || !a.axis_range.empty()))
    throw InvalidParameter("axis", "--axis and --axis-range need --model FILE (the default map is theta-rho: --rho-range)");
  const Model m = load_selected_model(a.model, cmd, a.p);
  jobs::RegimeMapConfig c;
  c.lattice = lattice_of(a.model, m);
  c.plane = a.plane;
  c.branch = a.branch;
  c.axis = a.axis;
  c.nx = a.res_x;
  c.ny = a.res_y;
  c.delta0_log = a.delta0_log;
  c.curves = !a.no_curves;
  c.figures = !a.no_figures;
  c.max_memory = a.max_memory;
  c.format = a.format;
  const bool resonant_plane = a.model.file.empty() || (a.plane == "delta0-omega" && m.name() == "resonant_chain");
  if (resonant_plane && (a.plane == "theta-rho" || a.plane == "delta0-omega")) refuse_other_plane_options(a);
  c.axis_range = range_option(a.axis_range, "axis-range");
  c.rho_range = range_option(a.rho_range, "rho-range");
  c.delta0_range = range_option(a.delta0_range, "delta0-range");
  c.omega_range = range_option(a.omega_range, "omega-range");
  with_option_names(jobs::regime_map_options(), [&] { jobs::validate(c, a.out); });
  const fs::path dir(a.out);
  const jobs::OutputLock lock(dir);
  const jobs::OutputListing earlier = jobs::list_output_files(dir);  // files of an earlier run
  jobs::Figures figures(dir);
  const jobs::RegimeMapResult result = with_option_names(jobs::regime_map_options(), [&] { return jobs::run(c); });
  json out = jobs::to_json(result, jobs::write(result, dir, figures));
  out["out"] = fs::absolute(dir).string();
  figures.finish(out);
  jobs::record_stale_files(dir, earlier, out);
  out["provenance"] = provenance_json();
  std::cout << out.dump(2) << '\n';
}

// ---- regime thresholds ----------------------------------------------------------------------

struct ThresholdsArgs {
  int scan = 0;
  bool json_flag = false;
  ModelSelection model;
  std::string branch, axis;
  std::vector<std::string> axis_range;
};

void run_thresholds(const ThresholdsArgs& a, const CLI::App& cmd) {
  jobs::RegimeThresholdsConfig c;
  if (a.model.file.empty()) {
    if (!a.model.set.empty() || !a.axis.empty() || !a.axis_range.empty() || !a.branch.empty())
      throw InvalidParameter("model", "--set, --axis, --axis-range and --branch need --model FILE (without it "
                                      "the paper's scenarios run)");
  } else {
    c.model = load_selected_model(a.model, cmd, Params{});
  }
  c.scan = a.scan;
  c.branch = a.branch;
  c.axis = a.axis;
  c.axis_range = range_option(a.axis_range, "axis-range");
  json out = with_option_names(jobs::regime_thresholds_options(), [&] { return jobs::to_json(jobs::run(c)); });
  out["provenance"] = provenance_json();
  std::cout << out.dump(a.json_flag ? -1 : 2) << '\n';
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
  const auto intervals_help = [](const char* key) { return schema_help(jobs::regime_intervals_options(), key); };
  in->add_option("--branch", ia->branch, intervals_help("branch"))->type_name("NAME");
  add_integer(*in, "--samples", ia->samples, config::intervals_samples.least, config::intervals_samples.most,
              intervals_help("samples"));
  in->add_flag("--json", ia->json_flag, "print the JSON on one line (default: indented)");
  in->add_option("--out", ia->out, intervals_help("out"))->type_name("DIR");
  add_examples(*in, {"lrchain regime intervals --branch acoustic --rho 1 --delta0 4/9"});
  in->callback([ia, in] { run_intervals(*ia, *in); });

  // map
  auto ma = std::make_shared<MapArgs>();
  auto* mp = regime->add_subcommand(
      "map",
      "Regime map written to --out: CSV pixel map (regime -1 outside band, 0 defocusing, "
      "1 focusing, 2 singular), boundary curves as CSV polylines per cause (traced by "
      "continuation), a gnuplot script and its PNG. theta-rho: Fig. 2 (rho on x, theta on y; "
      "default rho range " + range_text(jobs::default_rho_range(Branch::optical), "..") + " optical, " +
          range_text(jobs::default_rho_range(Branch::acoustic), "..") +
          " acoustic; branch both draws two panels). "
          "delta0-omega: Figs. 4-5 (kappa as given, paper: 1; default delta0 " +
          range_text(jobs::default_delta0_range, "..") + "; hatched "
      "focusing frequency bands from root-found intervals, and their number versus delta0). "
      "With --model FILE: the (parameter, theta) plane of any model parameter (--axis NAME, "
      "--axis-range lo hi), files regime_theta-NAME_BRANCH.csv.");
  add_model_options(*mp, ma->p, false);
  add_model_file_options(*mp, ma->model);
  const auto map_help = [](const char* key) { return schema_help(jobs::regime_map_options(), key); };
  mp->add_option("--axis", ma->axis, map_help("axis"))->type_name("NAME");
  mp->add_option("--axis-range", ma->axis_range, map_help("axis_range"))->expected(2)->type_name("NUM");
  mp->add_option("--plane", ma->plane, map_help("plane"))->type_name("NAME");
  mp->add_option("--branch", ma->branch, map_help("branch"))->type_name("NAME");
  mp->add_option("--out", ma->out, "output directory (created)")->required()->type_name("DIR");
  mp->add_option("--rho-range", ma->rho_range, map_help("rho_range"))->expected(2)->type_name("NUM");
  mp->add_option("--delta0-range", ma->delta0_range, map_help("delta0_range"))->expected(2)->type_name("NUM");
  mp->add_option("--omega-range", ma->omega_range, map_help("omega_range"))->expected(2)->type_name("NUM");
  mp->add_flag("--delta0-log", ma->delta0_log, map_help("delta0_log"));
  add_integer(*mp, "--nx", ma->res_x, config::map_pixels_x.least, config::map_pixels_x.most, map_help("nx"));
  add_integer(*mp, "--ny", ma->res_y, config::map_pixels_y.least, config::map_pixels_y.most, map_help("ny"));
  add_max_memory(*mp, ma->max_memory);
  add_figure_format(*mp);
  mp->add_option("--format", ma->format, map_help("format"))
      ->check(CLI::IsMember({"csv", "hdf5"}).description(""))
      ->type_name("csv|hdf5");
  mp->add_flag("--no-curves", ma->no_curves, map_help("curves"));
  mp->add_flag("--no-figures", ma->no_figures, "write the data and .gp scripts but draw no figures (no gnuplot run; default: figures)");
  add_examples(*mp, {"lrchain regime map --plane theta-rho --branch both --out out/fig2",
                      "lrchain regime map --plane delta0-omega --branch optical --rho 3 --out out/fig4"});
  mp->callback([ma, mp] { run_map(*ma, *mp); });

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
  const auto thresholds_help = [](const char* key) { return schema_help(jobs::regime_thresholds_options(), key); };
  add_integer(*th, "--scan", ta->scan, 10, 100'000, thresholds_help("scan"));
  th->add_flag("--json", ta->json_flag, "print the JSON on one line (default: indented)");
  add_model_file_options(*th, ta->model);
  th->add_option("--axis", ta->axis, thresholds_help("axis"))->type_name("NAME");
  th->add_option("--axis-range", ta->axis_range, thresholds_help("axis_range"))->expected(2)->type_name("NUM");
  th->add_option("--branch", ta->branch, thresholds_help("branch"))->type_name("NAME");
  add_examples(*th, {"lrchain regime thresholds", "lrchain regime thresholds --model fput --axis b --axis-range 0.1 2"});
  th->callback([ta, th] { run_thresholds(*ta, *th); });
}

}  // namespace lrchain::cli

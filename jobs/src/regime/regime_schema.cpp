// The regime jobs' option schemas (regime_schema.hpp): defaults from default-constructed configs and
// the default ranges of regime_job.hpp, help texts as `lrchain regime <job> --help` shows them.
#include "lrchain/jobs/regime_schema.hpp"

#include <fmt/format.h>

#include "lrchain/config/option_caps.hpp"
#include "lrchain/jobs/regime_job.hpp"

namespace lrchain::jobs {

namespace {

using nlohmann::json;

// "lo<sep>hi" of a default range.
std::string range_text(const Range& r, const char* sep) { return fmt::format("{:g}{}{:g}", r[0], sep, r[1]); }

std::string integer_range(const config::OptionCap& cap) { return fmt::format("[{}, {}]", cap.least, cap.most); }

// The axis of a model's map or scan (regime map and thresholds).
JobOption axis_option(std::string doc) {
  return {"axis", "--axis", "axis", {}, nullptr, false, "a parameter of the model", std::move(doc), "{doc}"};
}

std::vector<JobOption> make_intervals() {
  const RegimeIntervalsConfig d;
  return {
      {"branch", "--branch", "branch", {}, nullptr, false,
       "optical or acoustic; with --model: the model's branch names", "the branch",
       "optical or acoustic (default {default}); with --model: the model's branch names (default optical, or its "
       "only branch)",
       "optical"},
      {"samples", "--samples", "samples", {}, d.samples, false, integer_range(config::intervals_samples),
       "theta samples used to bracket the zeros", "{doc} (default {default})"},
      {"tolerance", "", "tolerance", {}, d.tolerance, false, "(0, 1e-2)", "accuracy of each interval end in theta"},
      {"out", "--out", "", {}, nullptr, false, "a directory (created)",
       "also write the intervals as HDF5 to result.h5 in this directory (lrchain.load reads it)",
       "{doc} (default: {default})", "none: only the JSON on stdout"},
  };
}

std::vector<JobOption> make_map() {
  const RegimeMapConfig d;
  const Range rho_optical = default_rho_range(Branch::optical), rho_acoustic = default_rho_range(Branch::acoustic);
  const std::string rho_note = range_text(rho_optical, " ") + " for optical or both, " + range_text(rho_acoustic, " ") +
                               " for acoustic";
  return {
      axis_option("with --model: the parameter on x (default rho for the resonant chain, else the model's first)"),
      {"axis_range", "--axis-range", "x", {}, nullptr, false, "lo < hi inside the parameter's range",
       "with --model: lo hi of the --axis parameter", "{doc} (default: {default})", "its declared range when bounded"},
      {"plane", "--plane", "", {}, d.plane, false, "theta-rho or delta0-omega", "the plane of the map",
       "theta-rho (default) or delta0-omega"},
      // (Python's maps take one branch, required: a map of one panel)
      {"branch", "--branch", "", {}, d.branch, false, "optical, acoustic or both; with --model: a branch name or both/all",
       "the branch", "optical, acoustic or both (default {default}); with --model: a branch name or both/all"},
      {"rho_range", "--rho-range", "rho", {}, nullptr, false, "inside rho's range", "theta-rho: rho lo hi",
       "{doc} (default {default})", rho_note},
      {"theta_range", "", "theta", {}, nullptr, false, "in (0, pi]", "theta-rho and theta-parameter: theta lo hi",
       "{doc} (default {default})", "pi/ny pi"},
      {"delta0_range", "--delta0-range", "delta0", {}, nullptr, false, "inside delta0's range",
       "delta0-omega: delta0 lo hi", "{doc} (default {default})", range_text(default_delta0_range, " ")},
      {"omega_range", "--omega-range", "omega", {}, nullptr, false, "each in [0, twice the top of the optical band]",
       "delta0-omega: omega lo hi", "{doc}, {range} (default: {default})", "the band over the delta0 range"},
      {"rho_log", "", "rho_log", {}, d.rho_log, false, "true|false", "theta-rho: geometric rho axis"},
      {"delta0_log", "--delta0-log", "delta0_log", {}, d.delta0_log, false, "true|false",
       "delta0-omega: logarithmic delta0 axis", "{doc} (default: linear)"},
      {"nx", "--nx", "", {}, d.nx, false, integer_range(config::map_pixels_x), "pixels along x (rho or delta0)",
       "{doc}, default {default}"},
      {"ny", "--ny", "", {}, d.ny, false, integer_range(config::map_pixels_y), "pixels along y (theta or omega)",
       "{doc}, default {default}"},
      {"curves", "--no-curves", "", {}, d.curves, false, "true|false", "trace the boundary curves",
       "skip tracing the boundary curves"},
      {"format", "--format", "", {}, d.format, false, "csv|hdf5",
       "data files in --out: csv (CSV, gnuplot scripts, figures) or hdf5 (also result.h5, or result_<branch>.h5 per "
       "branch: the map, its axes and boundary curves; lrchain.load reads them)", "{doc} (default {default})"},
  };
}

std::vector<JobOption> make_curves() {
  const RegimeCurvesConfig d;
  return {
      {"branch", "", "branch", {}, d.branch, false, "a branch name", "the branch"},
      {"axis", "", "axis", {}, nullptr, false, "rho or delta0; a model: any of its parameters",
       "the parameter on x", "", "rho for the resonant chain, else the model's first"},
      {"range", "", "lo", {}, nullptr, false, "finite, lo < hi (resonant chain: 0 < lo)", "lo (and ``hi``) of the axis", "",
       "the map's x range of this branch"},
      {"omega_plane", "", "omega_plane", {}, d.omega_plane, false, "true|false",
       "resonant chain, axis delta0: map theta to omega (Figs. 4-5)"},
  };
}

std::vector<JobOption> make_thresholds() {
  const RegimeThresholdsConfig d;
  return {
      {"scan", "--scan", "scan", {}, nullptr, false, "[10, 100000]", "scan points per scenario",
       "{doc} (default: {default})", "built-in 300-400; with --model 300"},
      axis_option("with --model: the scanned parameter (default rho / the model's first)"),
      {"axis_range", "--axis-range", "axis_range", {}, nullptr, false, "lo < hi inside the parameter's range",
       "with --model: lo hi of the scan", "{doc} (default: {default})", "its declared range when bounded"},
      {"branch", "--branch", "branch", {}, nullptr, false, "a branch name", "with --model: a branch name",
       "{doc} (default: {default})", "every branch"},
  };
}

}  // namespace

const std::vector<JobOption>& regime_intervals_options() { return schema_once<make_intervals>(); }
const std::vector<JobOption>& regime_map_options() { return schema_once<make_map>(); }
const std::vector<JobOption>& regime_curves_options() { return schema_once<make_curves>(); }
const std::vector<JobOption>& regime_thresholds_options() { return schema_once<make_thresholds>(); }

}  // namespace lrchain::jobs

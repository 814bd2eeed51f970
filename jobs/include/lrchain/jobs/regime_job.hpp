#pragma once
// The regime jobs (Sec. 3.3, Figs. 2, 4, 5): focusing theta-intervals, regime maps, boundary curves
// and the structure changes along a parameter (thresholds), of the paper's resonant chain (through
// Params and its specialised evaluators) or of any loaded model, each as one Config (defaults,
// ranges and documentation once) -> validate -> run -> Result -> write / to_json. The CLI's
// `lrchain regime ...` and Python's lrchain.regime translate their arguments into these Configs.
// Errors name the Config key in snake_case (InvalidParameter("rho_range")).
#include <array>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "lrchain/model.hpp"
#include "lrchain/params.hpp"
#include "lrchain/regime/boundary_curves.hpp"
#include "lrchain/regime/focusing_intervals.hpp"
#include "lrchain/regime/grid_axis.hpp"
#include "lrchain/regime/paper_thresholds.hpp"
#include "lrchain/regime/regime_events.hpp"

namespace lrchain::jobs {

class Figures;

using Range = std::array<double, 2>;  // lo hi

// Which lattice a regime job evaluates: the paper's resonant chain at `params` (its specialised
// evaluators; the default) or a loaded model (`model`, e.g. a model file).
struct RegimeLattice {
  Params params;               // the resonant chain's parameters (used when `model` is empty)
  std::shared_ptr<const Model> model;  // a loaded model; null: the resonant chain at `params`
};

// The resonant chain (its specialised path) at the parameters of a loaded resonant_chain model.
RegimeLattice resonant_chain_lattice(const Model& resonant_chain);

// The parameter a map, curves or a scan use when none is named: rho for the resonant chain, else the
// model's first parameter.
std::string default_axis(const RegimeLattice& lattice);

// ---- intervals ------------------------------------------------------------------------------

// Focusing theta-intervals of one branch (`lrchain regime intervals`, lrchain.regime.intervals).
struct RegimeIntervalsConfig {
  RegimeLattice lattice;
  // Branch name; empty: optical (or a model's only branch). Resonant chain: optical | acoustic.
  std::string branch;
  // theta samples used to bracket the zeros, in [8, 1e7] (config::intervals_samples).
  int samples = 2048;
  // accuracy of each interval end in theta, in (0, 1e-2).
  double tolerance = 1e-12;
};

struct RegimeIntervalsResult {
  std::string branch;          // the branch's name
  nlohmann::json model;        // model_json of the lattice
  regime::RegimeStructure structure;
  double tolerance = 1e-12;
};

void validate(const RegimeIntervalsConfig& config);
RegimeIntervalsResult run(const RegimeIntervalsConfig& config);
// {"branch", "model", "intervals", "boundaries", "theta_tolerance"} (no provenance).
nlohmann::json to_json(const RegimeIntervalsResult& result);

// ---- map ------------------------------------------------------------------------------------

// A regime map (`lrchain regime map`, lrchain.regime.*_map): sign(omega'' h_tilde) on a pixel grid,
// the boundary curves between the regions, and (delta0-omega) the root-found focusing bands.
struct RegimeMapConfig {
  RegimeLattice lattice;
  // "theta-rho" (Fig. 2, the default), "delta0-omega" (Figs. 4-5; resonant chain only) or, for a
  // model, "theta-parameter" (the (axis, theta) plane; "theta-rho" means the same there).
  std::string plane = "theta-rho";
  // "both" (the default: optical and acoustic, or every branch of a model; "all" too), or one name.
  std::string branch = "both";
  // model: the parameter on x (default rho for the resonant chain, else the model's first).
  std::string axis;
  // model: lo hi of `axis` (default: rho 0.01 30 optical, 0.01 2.5 acoustic for the resonant
  // chain, else the parameter's declared range when bounded, open ends moved in by 1e-3 of it).
  std::optional<Range> axis_range;
  // theta-rho: rho lo hi, inside rho's range (default 0.01 30 optical, 0.01 2.5 acoustic).
  std::optional<Range> rho_range;
  // theta-rho and theta-parameter: theta lo hi in (0, pi] (default pi/ny pi).
  std::optional<Range> theta_range;
  // delta0-omega: delta0 lo hi, inside delta0's range (default 0.001 1).
  std::optional<Range> delta0_range;
  // delta0-omega: omega lo hi, each in [0, 2 omega_top], omega_top the top of the optical band over
  // the delta0 range (default: the branch's band over the delta0 range, default_omega_range).
  std::optional<Range> omega_range;
  bool rho_log = false;     // theta-rho: geometric rho axis
  bool delta0_log = false;  // delta0-omega: geometric delta0 axis
  int nx = 600;             // pixels along x, in [2, 20000] (config::map_pixels_x)
  int ny = 600;             // pixels along y, in [2, 20000] (config::map_pixels_y)
  bool curves = true;       // trace the boundary curves
  bool inset = true;        // theta-rho acoustic: a finer map of Fig. 2's inset (for the figure)
  bool bands = true;        // delta0-omega: root-found focusing bands per delta0 (for the figure)
  bool figures = true;      // draw the figures (write: gnuplot); the scripts are always written
  // memory limit in bytes for the map; 0: the machine's available memory.
  double max_memory = 0;
  // csv | hdf5: hdf5 also writes the map as HDF5 beside the CSV files (regime_hdf5.hpp: write_hdf5).
  std::string format = "csv";
};

// The defaults of a map's ranges (the CLI's, the reference).
Range default_rho_range(Branch branch);  // 0.01 30 optical, 0.01 2.5 acoustic
inline constexpr Range default_delta0_range{0.001, 1.0};
// The branch's band over [delta0 lo, hi] (bands grow with delta0): optical [0.98 omega_lo(lo),
// 1.02 omega_hi], acoustic [0, 1.02 omega_hi], omega_hi the larger top of the two ends.
Range default_omega_range(const Params& params, Branch branch, const Range& delta0_range);

// One panel of a map: one branch.
struct RegimeMapPanel {
  std::string branch;
  Branch resonant_branch = Branch::optical;  // resonant chain through Params
  regime::GridAxis x, y;
  std::vector<std::int8_t> values;  // values[j * x.n + i] at (x.at(i), y.at(j)); regime_map.hpp
  double map_seconds = 0;
  bool curves_traced = false;
  std::vector<regime::BoundaryCurve> curves;  // (x, theta), or (delta0, omega)
  double curves_seconds = 0;
  // theta-rho acoustic: a finer map of the narrow region at small rho (Fig. 2's inset).
  std::optional<regime::GridAxis> inset_x, inset_y;
  std::vector<std::int8_t> inset_values;
  // delta0-omega: per delta0 pixel, the root-found focusing intervals and their frequencies, and
  // the band edges omega(0), omega(pi).
  struct Band {
    regime::FocusingInterval theta;
    double omega_lo = 0, omega_hi = 0;
  };
  std::vector<std::vector<Band>> bands;
  std::vector<std::array<double, 2>> band_edges;
};

struct RegimeMapResult {
  std::string plane;  // "theta-rho", "delta0-omega" or "theta-<axis>" (a model)
  std::string axis;   // x axis name: "rho", "delta0" or the model's parameter
  bool resonant_chain = true;  // the resonant chain through Params (else a model)
  Params params;               // resonant chain
  std::string model_name;      // model
  nlohmann::json model;        // model_json of the lattice
  int nx = 0, ny = 0;
  bool delta0_log = false;
  bool curves = true, figures = true;
  std::string format = "csv";  // the config's: hdf5 also writes the HDF5 file(s)
  std::vector<RegimeMapPanel> panels;
};

// Every option, the plane's ranges, the memory and (with out_dir) the output space and directory;
// nothing is written.
void validate(const RegimeMapConfig& config, const std::filesystem::path& out_dir = {});
RegimeMapResult run(const RegimeMapConfig& config);

// The files of a written map: per figure (theta planes: one; delta0-omega: one per branch) the
// files in the order written and whether its figure was drawn (empty: not asked).
struct RegimeMapFiles {
  std::vector<std::vector<std::string>> files;
  std::vector<std::optional<bool>> drawn;
  std::vector<std::string> hdf5;  // format hdf5: the HDF5 files written
};
// Pixel maps and curves as CSV, the gnuplot scripts and (result.figures) their figures in dir; format
// hdf5: also the HDF5 files (regime_hdf5.hpp), listed in RegimeMapFiles::hdf5.
RegimeMapFiles write(const RegimeMapResult& result, const std::filesystem::path& dir, jobs::Figures& figures);
// The JSON summary of `lrchain regime map` (without out, figures, stale files, provenance); format hdf5
// adds "hdf5_files".
nlohmann::json to_json(const RegimeMapResult& result, const RegimeMapFiles& files);

// ---- curves ---------------------------------------------------------------------------------

// Boundary curves in the (parameter, theta) plane (lrchain.regime.boundary_curves).
struct RegimeCurvesConfig {
  RegimeLattice lattice;
  std::string branch = "optical";  // a branch name
  // The parameter: resonant chain "rho" (the default) or "delta0"; a model: any of its parameters
  // (default rho for the resonant chain, else the model's first).
  std::string axis;
  // lo hi of `axis`, finite, lo < hi (resonant chain: 0 < lo); default: the map's x range of this
  // branch (default_axis_range).
  std::optional<Range> range;
  bool omega_plane = false;  // resonant chain, axis delta0: map theta to omega (Figs. 4-5)
};

// The default x range of a map (and of boundary curves) along `axis` on `branch`: resonant chain rho
// default_rho_range, delta0 default_delta0_range; a model as RegimeMapConfig::axis_range.
Range default_axis_range(const RegimeLattice& lattice, const std::string& axis, const std::string& branch);

void validate(const RegimeCurvesConfig& config);
std::vector<regime::BoundaryCurve> run(const RegimeCurvesConfig& config);

// ---- thresholds -----------------------------------------------------------------------------

// Structure changes along a parameter (`lrchain regime thresholds`, lrchain.regime.thresholds):
// the paper's scenarios (resonant chain) or the events along one parameter of a model.
struct RegimeThresholdsConfig {
  std::optional<Model> model;  // empty: the paper's scenarios
  int scan = 0;                // scan points, in [10, 100000]; 0: built-in (300-400; model: 300)
  std::string branch;          // model: a branch name (empty: every branch)
  std::string axis;            // model: the scanned parameter (default rho / the model's first)
  std::optional<Range> axis_range;  // model: lo hi (default as RegimeMapConfig::axis_range)
};

struct RegimeThresholdScan {
  std::string name;  // paper scenario
  std::string branch, axis;
  regime::GridAxis scan;
  std::vector<regime::RegimeEvent> events;
  std::vector<regime::MatchedThreshold> paper_values;  // paper scenario
  std::string paper_text;
  nlohmann::json model;  // paper scenario: its base
  double seconds = 0;
};

struct RegimeThresholdsResult {
  bool paper = true;
  nlohmann::json model;  // model
  std::vector<RegimeThresholdScan> scans;
};

void validate(const RegimeThresholdsConfig& config);
RegimeThresholdsResult run(const RegimeThresholdsConfig& config);
// {"scenarios"} (paper) or {"model", "scans"} (no provenance).
nlohmann::json to_json(const RegimeThresholdsResult& result);

}  // namespace lrchain::jobs

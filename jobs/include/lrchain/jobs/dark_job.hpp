#pragma once
// The dark-breather job (Secs. 5.3-5.4, Figs. 17-25) for the resonant chain and any model file: one
// DarkConfig -> validate -> run (solve, floquet, continue, evolve) -> DarkResult -> write (CSV,
// gnuplot, HDF5 in an output directory) and to_json (the summary `lrchain dark` prints). The
// `lrchain dark` command, lrchain.dark and the "dark continue" sweep are adapters onto it.
#include <atomic>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Dense>
#include <nlohmann/json.hpp>

#include "lrchain/jobs/breather_solver.hpp"
#include "lrchain/model.hpp"
#include "lrchain/params.hpp"
#include "lrchain/sim/dark/continuation.hpp"
#include "lrchain/sim/dark/evolution.hpp"
#include "lrchain/sim/dark/floquet.hpp"
#include "lrchain/sim/dark/measures.hpp"
#include "lrchain/sim/dark/perturbation.hpp"
#include "lrchain/sim/dark/resonant_chain_shooting.hpp"
#include "lrchain/compiled_model_abi.h"

namespace lrchain::jobs::dark {

// What a dark job computes after Newton's solution.
enum class DarkStep {
  solve,     // Newton on the period map from the eq:xy_app seed (or the model's seed)
  floquet,   // solve, then the Floquet multipliers of the monodromy matrix (Sec. 5.4)
  branch,    // solve, then pseudo-arclength continuation in omega_b with Floquet at every point
  evolve,    // solve, then direct integration over floor(t_end / T_b) periods (Figs. 21, 22, 25)
};

// Every option of a dark job, with its default and range; validate() names a refused one by its
// key (snake_case, e.g. "omega_b"; the CLI spells it --omega-b, Python omega_b=).
struct DarkConfig {
  DarkStep step = DarkStep::solve;
  // The lattice: the resonant chain through `params` (model == nullptr), or a loaded model with its
  // generated lattice kernels (both owned by the caller, alive during run and write).
  Params params;
  const Model* model = nullptr;
  const lrchain_lattice_kernels* kernels = nullptr;
  double omega_b = 0;  // breather frequency, on the side of the edge where (omega_b - omega) h > 0 (required)
  std::string branch;  // optical|acoustic, or a model's branch; "": optical / the model's first defocusing edge
  std::string center = "bond";      // bond (n0 = 1/2) | site (n0 = 0)
  std::string mode = "reversible";  // shooting over a half/quarter period | full (the whole period, a check)
  // Lattice sites per field (periodic ends): odd at a theta = pi edge, even at theta = 0; none:
  // 101 or 100 (default_dark_sites).
  std::optional<Index> sites;
  double tolerance = 1e-11;         // Newton and corrector: converged when max|F| <= tolerance, in (0, 1)
  Index max_iterations = 20;        // Newton iterations, >= 1
  bool full_monodromy = false;      // floquet: integrate the full period (check of the reversible reduction)
  // branch:
  Index points = 100;       // maximum number of branch points, the first included, in [1, 1e6]
  double ds = 0.1;          // initial pseudo-arclength step in (0, 1] (adapted within [1e-5, 1])
  double omega_min = 0;     // stop when omega_b falls below this
  double omega_max = 0;     // stop when omega_b rises above this; 0: the band edge (none above a rising edge)
  bool branch_floquet = true;  // Floquet multipliers at every branch point
  // The continued parameter: omega_b, or (model files) one of the model's parameters at fixed omega_b
  std::string parameter = "omega_b";
  // Where the continuation goes and ends (its last point solved there): required for a model
  // parameter, in its range; for omega_b it replaces omega_min (below omega_b) or omega_max (above)
  std::optional<double> to;
  // evolve:
  double t_end = 0;   // integration time, at least one period T_b = 2 pi/omega_b (required)
  Index samples = 24;  // samples of x_n(t) per period for the position measure, in [4, 1e6]
  std::string perturb = "none";  // none | unstable (the largest Floquet multiplier's eigenvector) | random
  double perturb_size = 1e-6;    // max-norm of the perturbation of [Z(0), Zdot(0)], in (0, 1)
  std::uint64_t seed = 1;        // random: the generator's seed
  // resources and files:
  // with a model file, solve/floquet/evolve: the dense path or the matrix-free one (breather_solver.hpp);
  // continue, full mode and the paper chain's own shooting are dense
  BreatherSolverOptions krylov;
  double max_memory = 0;    // bytes the job may use; 0: the machine's available memory
  std::string out;          // output directory ("": no files)
  std::string format = "csv";  // csv | hdf5 (also out/result.h5: jobs/model_dark_hdf5.hpp, dark_evolution_hdf5.hpp)
};

// Checks every option, the memory the job needs and the output directory before anything is
// computed or written: InvalidParameter naming the DarkConfig key, InputError for `out`.
void validate(const DarkConfig& c);

// The default number of sites at a band edge theta: 101 at pi (a staggered breather needs an odd
// ring), 100 at 0 (a pair of breathers half a ring apart needs an even one).
constexpr Index default_dark_sites(double edge_theta) { return edge_theta != 0 ? 101 : 100; }

// c.sites, or the default at the edge the job's breather bifurcates from (the resonant chain's is
// at theta = pi; a model's from its branch and regimes).
Index dark_sites(const DarkConfig& c);

// What a front end observes while the job runs.
struct DarkRunHooks {
  const std::atomic<bool>* stop = nullptr;  // set (SIGINT): the branch/evolution ends after the current point/period
  bool stop_integrations = false;           // `stop` also ends a running integration (Interrupted)
  std::function<void(const sim::dark::NewtonRecord&)> newton_progress;  // after every Newton iteration
  std::function<void(const sim::dark::BranchPoint&)> on_point;          // after every branch point
  std::function<void(double fraction)> evolution_progress;  // after every period of evolve: periods done / periods
};

// The band edge the breather bifurcates from and the lattice's variables.
struct DarkEdge {
  std::string branch;           // the branch's name
  double theta = 0;             // pi (or 0 for a model's edge)
  double omega = 0;             // edge frequency omega(theta)
  double curvature = 0, h_tilde = 0, lambda = 0;  // (model files) omega'', h - lambda beta, lambda
  bool mean_flow = true;        // strain form (translation-invariant) or displacement form
  int fields = 2;               // lattice variables per site
  std::vector<std::string> variables;  // CSV names: x, y (the chain); r, w1, ... or u0, u1, ... (models)
  std::vector<std::string> variable_meanings;  // "r[n] = u0[n] - u0[n-1]", ... (models)
  std::vector<std::string> one_sided_contacts;  // the model's contact bonds by name (empty: smooth)
};

// What a dark job computed: its config, the edge, Newton, and the step's measures/Floquet, branch or evolution.
struct DarkResult {
  DarkConfig config;
  DarkEdge edge;
  sim::dark::NewtonResult newton;  // not converged: the job stopped there
  Eigen::VectorXd z0, seed;        // Z(0) and the seed, field-major (sites per variable)
  Eigen::VectorXd z_period;        // Z(T_b) by direct integration (when config.out is set: the profile)
  sim::dark::DarkMeasures measures;
  std::optional<sim::dark::FloquetResult> floquet;
  std::string monodromy;  // "full period" | "reversible reduction"
  std::optional<Index> contact_changes_per_period;  // models with one-sided contacts
  sim::dark::BranchResult branch;
  // (model files, continue) the reflection family imposed on the branch, e.g. "i -> (61 - i) mod 61
  // with sign +, at all times"; empty: none (the lattice has no reflection symmetry, or the paper chain's own families)
  std::string symmetry;
  sim::dark::DarkEvolution evolution;
  // evolve --perturb: the perturbation added to the breather's start (empty vector: none)
  sim::dark::DarkPerturbation perturbation;
  std::optional<KrylovRecord> krylov;  // the matrix-free path's record (floquet: the leading multipliers), absent on the dense one
  bool model_file() const { return config.model != nullptr; }
};

// Runs the job from a validated config. A Newton that does not converge ends the job and is reported
// in result.newton, a corrector failing at once in result.branch (see failure()), not thrown.
DarkResult run(const DarkConfig& c, const DarkRunHooks& hooks = {});

// The failure to report (Newton not converged, a branch of fewer than two points), or nullopt.
std::optional<std::string> failure(const DarkResult& r);

// The JSON summary `lrchain dark` prints (model, options, edge, Newton history, measures, Floquet,
// branch or evolution summary, provenance; "failure" null unless the job failed).
nlohmann::json to_json(const DarkResult& r);

// Writes the job's files into `out` (profile.csv, multipliers.csv, branch.csv, floquet_moduli.csv,
// evolution files, result.h5, gnuplot scripts and figures) and returns to_json(r) completed with
// "figures", "figures_skipped" and "stale_files" (files of an earlier run in `out` it did not write).
nlohmann::json write(const DarkResult& r, const std::filesystem::path& out);

}  // namespace lrchain::jobs::dark

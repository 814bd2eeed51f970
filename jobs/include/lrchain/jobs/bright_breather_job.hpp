#pragma once
// The exact bright-breather job for any model file (the paper's chain too, as the shipped model
// resonant_chain): one BrightBreatherConfig -> validate -> run (solve, floquet) -> BrightBreatherResult
// -> write (CSV, gnuplot, summary.json in an output directory) and to_json (the summary
// `lrchain bright` prints). Newton on the same time-reversible shooting as the dark breathers
// (sim/dark/shooting.hpp: Zdot(T_b/2) = 0 from Z(0) at rest), seeded by the NLS bright breather at the
// focusing band edge omega_b leaves (sim/bright/bright_seed.hpp), after the non-resonance check
// (sim/bright/linear_bands.hpp); a converged zero is kept only if it is a localized bright breather
// (sim/bright/bright_profile.hpp); Floquet multipliers with the trivial +1 ones removed
// (sim/bright/bright_floquet.hpp). docs/bright-breathers.md.
#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Dense>
#include <nlohmann/json.hpp>

#include "lrchain/coefficients.hpp"
#include "lrchain/jobs/breather_solver.hpp"
#include "lrchain/model.hpp"
#include "lrchain/sim/bright/branch_bifurcations.hpp"
#include "lrchain/sim/bright/bright_evolution.hpp"
#include "lrchain/sim/bright/bright_floquet.hpp"
#include "lrchain/sim/bright/bright_profile.hpp"
#include "lrchain/sim/bright/krein_signature.hpp"
#include "lrchain/sim/bright/linear_bands.hpp"
#include "lrchain/sim/dark/continuation.hpp"
#include "lrchain/sim/dark/perturbation.hpp"
#include "lrchain/sim/dark/shooting_problem.hpp"
#include "lrchain/compiled_model_abi.h"

namespace lrchain::jobs::bright_breather {

// What a bright-breather job computes after Newton's solution.
enum class BrightStep {
  solve,    // Newton on the half-period map from the NLS seed, then the localization check
  floquet,  // solve, then the Floquet multipliers of the full-period monodromy matrix
  branch,   // solve, then pseudo-arclength continuation in omega_b away from the band edge
  evolve,   // solve, Floquet, then direct integration over `periods` periods (bright_evolution.hpp)
};

// Every option of the job, with its default and range (bright_breather_schema.hpp); validate() names a
// refused one by its key (snake_case: omega_b; the CLI spells it --omega-b).
struct BrightBreatherConfig {
  BrightStep step = BrightStep::solve;
  // The lattice: a loaded model and its generated lattice kernels (owned by the caller, alive during
  // run and write).
  const Model* model = nullptr;
  const lrchain_lattice_kernels* kernels = nullptr;
  double omega_b = 0;              // breather frequency, <= 10 x the top band, outside every band, non-resonant (required)
  std::string branch;              // the branch whose edge the breather leaves; "": the focusing edge nearest omega_b
  std::string center = "site";     // site (n0 = 0) | bond (n0 = 1/2)
  // Newton's start: nls (the NLS bright breather at the focusing edge) | anti-continuum (one oscillator,
  // two for bond, at coupling 0, continued in `coupling` to its value; on-site models; anti_continuum.hpp)
  std::string start = "nls";
  std::string coupling = "C";      // anti-continuum: the model parameter that couples the cells (0 in its range)
  Index sites = 101;               // odd, >= 9: lattice sites per field (periodic ends, centre in the middle)
  double tolerance = 1e-11;        // Newton: converged when max|F| <= tolerance, in (0, 1)
  Index max_iterations = 20;       // Newton iterations, >= 1
  double tail_tolerance = 1e-3;    // localized: max |Z| on the ring's far quarter <= this x the peak, in (0, 1)
  double unit_tolerance = 1e-6;    // floquet: |lambda| > 1 + this is unstable, in (0, 1)
  // branch (continue): within the non-resonant window around omega_b, on the edge's outer side
  Index points = 20;               // maximum number of branch points, the first included, in [1, 1e6]
  double ds = 0.05;                // initial pseudo-arclength step in (Z(0), omega_b), in (0, 1]
  bool branch_floquet = true;      // Floquet multipliers at every branch point
  // continue with Floquet: each multiplier crossing bisected (breathers re-solved between its bracketing
  // points) to a bracket at most this wide in the continued parameter, in [0, 1); 0: bracketed only
  double locate_tolerance = 1e-6;
  // The continued parameter: omega_b, or one of the model's parameters at fixed omega_b (e.g. the
  // coupling C of klein_gordon towards the anti-continuum limit C = 0)
  std::string parameter = "omega_b";
  // Where the continuation ends, its last point solved there: required for a model parameter (in its
  // range); for omega_b optional (none: away from the edge to the end of the non-resonant window)
  std::optional<double> to;
  // evolve: the breather (perturbed) integrated over this many periods T_b, in [1, 1e6]
  Index periods = 50;
  std::string perturb = "none";  // none | unstable (the largest Floquet multiplier's eigenvector) | random
  double perturb_size = 1e-6;    // max-norm of the perturbation of [Z(0), Zdot(0)], in (0, 1)
  std::uint64_t seed = 1;        // random: the generator's seed
  // solve, floquet: the dense path or the matrix-free one (breather_solver.hpp); continue is dense
  BreatherSolverOptions krylov;
  double max_memory = 0;           // bytes the job may use; 0: the machine's available memory
  std::string out;                 // output directory ("": no files)
  std::string format = "csv";      // csv | hdf5: hdf5 also writes result.h5 in `out` (bright_breather_hdf5.hpp)
};

// Checks every option, the non-resonance of omega_b, its focusing edge, the memory the job needs and
// the output directory, before anything is computed or written: InvalidParameter naming the key
// (omega_b for a resonance or no focusing edge), InputError for `out`.
void validate(const BrightBreatherConfig& c);

// What a front end observes while the job runs.
struct BrightBreatherHooks {
  std::function<void(const sim::dark::NewtonRecord&)> newton_progress;  // after every Newton iteration
  std::function<void(const sim::dark::BranchPoint&)> on_point;          // after every branch point
};

// The band edge the breather leaves and the NLS seed's coefficients there.
struct BrightEdge {
  std::string branch;
  double theta = 0;                   // pi or 0
  NlsCoefficients nls;                // omega, omega'', h_tilde, lambda at the edge
  double amplitude = 0;               // 2 M2 = 2 sqrt(2 (omega_b - omega) / h_tilde): the seed's peak of u_0
  double inverse_width = 0;           // a = sqrt(2 (omega - omega_b) / omega'')
  bool mean_flow = false;             // strain form (translation-invariant) or displacement form (on-site)
  int fields = 1;
  std::vector<std::string> variables;          // r, w1, ... or u0, u1, ...
  std::vector<std::string> variable_meanings;  // "r[n] = u0[n] - u0[n-1]", ...
  std::vector<std::string> one_sided_contacts;
};

struct BrightBreatherResult {
  BrightBreatherConfig config;
  BrightEdge edge;
  std::vector<sim::bright::LinearBand> bands;
  Index harmonics_checked = 0;      // k omega_b checked against the bands, k = 1 .. this
  sim::dark::NewtonResult newton;   // not converged: the job stopped there
  Eigen::VectorXd seed, z0;         // Newton's start (the NLS seed, or the continued anti-continuum orbit) and Z(0), field-major
  // start = anti-continuum: the excited oscillators' amplitude at coupling 0 and the continuation in the
  // coupling from 0 to its value (its last point is the seed); start_failure says why it did not get there
  double anti_continuum_amplitude = 0;
  sim::dark::BranchResult anti_continuum_branch;
  std::string start_failure;
  sim::bright::BrightProfile seed_profile, profile;
  double seed_difference = 0;       // max |Z(0) - seed| / max |Z(0)|
  std::string rejected;             // why a converged Newton zero is no localized bright breather ("": it is)
  std::optional<sim::bright::BrightFloquet> floquet;
  // floquet (dense): the Krein signatures of the multipliers on the upper unit circle (krein_signature.hpp)
  std::vector<sim::bright::KreinMultiplier> krein;
  // branch: the continuation (sim/dark/continuation.hpp), each point's profile and (branch_floquet)
  // multipliers; points after the first that is no localized breather are dropped (branch.stop_reason).
  sim::dark::BranchResult branch;
  std::vector<sim::bright::BrightProfile> branch_profiles;
  std::vector<sim::bright::BrightFloquet> branch_floquets;
  // folds (located on the interpolant) and multiplier crossings at +1, -1, exp(+-2 pi i/3) and Krein
  // collisions (bracketed, then located by bisection: locate_tolerance) along the kept points
  // (sim/bright/branch_bifurcations.hpp)
  std::vector<sim::bright::BranchBifurcation> bifurcations;
  // branch_floquet: per point the Krein signatures of the multipliers on the upper unit circle
  // (krein_signature.hpp; strain form: of the eigenvectors lifted to displacements)
  std::vector<std::vector<sim::bright::KreinMultiplier>> branch_krein;
  // the non-resonant window of omega_b (high: inf when unbounded); a model parameter: its start and c.to
  double window_low = 0, window_high = 0;
  // evolve: the perturbation added to the start (empty vector: none), the evolution, and the growth
  // rate ln(max |lambda|) / T_b the largest non-trivial Floquet multiplier predicts (floquet is set)
  sim::dark::DarkPerturbation perturbation;
  std::optional<sim::bright::BrightEvolution> evolution;
  double predicted_growth_rate = 0;
  std::optional<KrylovRecord> krylov;  // the matrix-free path's record (floquet: the leading multipliers), absent on the dense one
  double seconds = 0;               // wall time of run()
};

// Runs the job from a validated config. A Newton that does not converge, or a zero that is no
// localized breather, ends the job and is reported (failure()), not thrown. evolve with perturb
// unstable on a breather with no unstable multiplier throws InvalidParameter("perturb").
BrightBreatherResult run(const BrightBreatherConfig& c, const BrightBreatherHooks& hooks = {});

// Why the job failed (Newton, or the converged zero is no bright breather), or nullopt.
std::optional<std::string> failure(const BrightBreatherResult& r);

// The JSON summary `lrchain bright` prints: model, options, bands and harmonics checked, edge and seed,
// Newton history, profile, Floquet (trivial multipliers, pairing defect, |det M - 1|), provenance.
nlohmann::json to_json(const BrightBreatherResult& r);

// Writes profile.csv (n, Z(0) and the seed per variable), multipliers.csv (floquet), branch.csv
// (continue: omega_b, peak, norm, width, stability per point) and bifurcations.csv (continue), their gnuplot figures and summary.json into `out`
// (format hdf5: also result.h5); returns to_json(r) with "figures" and "figures_skipped".
nlohmann::json write(const BrightBreatherResult& r, const std::filesystem::path& out);

}  // namespace lrchain::jobs::bright_breather

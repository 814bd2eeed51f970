#pragma once
// How the exact-breather jobs (bright, and dark with a model file) solve and analyse a breather: the
// dense path (the full Jacobian / monodromy per Newton step, O(N^2.3)) or the matrix-free one
// (Newton-Krylov and Arnoldi on tangent products, sim/dark/newton_krylov.hpp and
// sim/dark/krylov_floquet.hpp; a bright breather's multipliers from its core window, certified by
// full-lattice residuals, sim/bright/windowed_floquet.hpp; a dark one's at a theta = pi edge from its
// window and its background's Floquet-Bloch spectrum, sim/dark/windowed_dark_floquet.hpp), chosen by the
// number of sites unless forced.
#include <optional>
#include <string>

#include <Eigen/Dense>
#include <nlohmann/json.hpp>

#include "lrchain/index.hpp"
#include "lrchain/sim/bright/windowed_floquet.hpp"
#include "lrchain/sim/dark/krylov_floquet.hpp"
#include "lrchain/sim/dark/newton_krylov.hpp"
#include "lrchain/sim/dark/windowed_dark_floquet.hpp"

namespace lrchain::jobs {

struct BreatherSolverOptions {
  std::string solver = "auto";  // auto | dense | krylov; auto: krylov above krylov_sites sites
  Index krylov_sites = 400;     // auto: the matrix-free path above this many sites, >= 9
  Index krylov_band = 12;       // Newton-Krylov preconditioner half-width in sites, >= 1
  Index floquet_count = 20;     // matrix-free Floquet: the leading (dark) or localized (bright) multipliers, >= 1
  std::string dark_floquet = "auto";  // matrix-free dark Floquet: auto | window | arnoldi; auto: window above krylov_sites
};

// InvalidParameter naming the key (solver, krylov_sites, krylov_band, floquet_count, dark_floquet).
void validate(const BreatherSolverOptions& o);

// Whether a job on `sites` sites takes the matrix-free path.
bool use_krylov(const BreatherSolverOptions& o, Index sites);

// Whether a matrix-free dark Floquet step on `sites` sites (theta = pi edge) takes the window, not Arnoldi.
bool use_dark_window(const BreatherSolverOptions& o, Index sites);

// What the matrix-free path did (absent from a dense run's result and JSON).
struct KrylovRecord {
  sim::dark::NewtonKrylovStats newton;
  std::optional<sim::dark::KrylovFloquetResult> floquet;     // Arnoldi (dark)
  std::optional<sim::bright::WindowedFloquet> windowed;      // core window, certified (bright)
  std::optional<sim::dark::WindowedDarkFloquet> dark_windowed;  // dip window and background (dark, theta = pi)
  double solve_seconds = 0, floquet_seconds = 0;
};

nlohmann::json to_json(const KrylovRecord& r);

// Newton on `shooting` from q0: dense (newton_solve) or, when use_krylov, Newton-Krylov with its
// record started in `record`.
sim::dark::NewtonResult solve_breather(const sim::dark::DarkShooting& shooting, Eigen::VectorXd q0, double omega_b,
                                       const sim::dark::NewtonOptions& newton, const BreatherSolverOptions& o,
                                       std::optional<KrylovRecord>& record);

// The leading floquet_count multipliers by Arnoldi into record->floquet (record present).
void krylov_floquet(const sim::dark::DarkShooting& shooting, const Eigen::VectorXd& z0, double omega_b,
                    const BreatherSolverOptions& o, KrylovRecord& record);

// The floquet_count largest-modulus localized multipliers of a bright breather from its core window,
// certified on the full lattice, into record.windowed (record present).
void windowed_floquet(const sim::dark::DarkShooting& shooting, const sim::bright::WindowLattice& lattice,
                      const Eigen::VectorXd& z0, double omega_b, const BreatherSolverOptions& o, double unit_tolerance,
                      KrylovRecord& record);

// The floquet_count largest-modulus localized multipliers of a dark breather (theta = pi edge) from its
// window, certified on the full lattice, and its background's Floquet-Bloch multipliers, into
// record.dark_windowed (record present); the window's and background's Newton to newton_tolerance.
void windowed_dark_floquet(const sim::dark::DarkShooting& shooting, const sim::bright::WindowLattice& lattice,
                           const Eigen::VectorXd& z0, double omega_b, const BreatherSolverOptions& o,
                           double newton_tolerance, KrylovRecord& record);

}  // namespace lrchain::jobs

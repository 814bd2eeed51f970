#pragma once
// The HDF5 files of exact dark breathers (Sec. 5.3-5.4): one writer per result, used by `lrchain dark
// solve|floquet|continue --format hdf5` and by Python's `result.to_hdf5(path)` (same file, h5py reads it).
//
// Root attributes of both: lrchain_result ("DarkSolution" or "Branch"), lrchain_version, git_commit,
// model (JSON text: {"name": "resonant_chain", "file_hash", "parameters": {alpha, delta0, kappa, rho}}).
// A solution: attributes omega_b, omega_edge; datasets n, x, y, x_seed, y_seed, newton_residuals;
//   group measures (attributes norm_squared, K_x, K_y, C_x, C_y, E_b, max_strain); with Floquet
//   multipliers, group floquet: dataset multipliers (complex, h5py's {r, i}), attributes kind,
//   max_modulus, max_real, max_period_doubling, max_oscillatory, near_one, pairing_defect,
//   conjugation_defect, log_det.
// A branch of P points on N sites: datasets omega_b, tangent_omega, residual (P), iterations (P,
//   int32), x, y (P x N), turning_points (or the attribute "[]" when there are none); attribute
//   stop_reason; group measures with one dataset (P) per measure; with Floquet multipliers, group
//   floquet: multipliers (P x 4N complex), one dataset (P) per scalar, attribute kind (JSON list).
#include <complex>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "lrchain/index.hpp"
#include "lrchain/params.hpp"
#include "lrchain/sim/dark/continuation.hpp"
#include "lrchain/sim/dark/floquet.hpp"
#include "lrchain/sim/dark/measures.hpp"
#include "lrchain/sim/dark/resonant_chain_shooting.hpp"

namespace lrchain::jobs {
class Hdf5TreeFile;
}

namespace lrchain::jobs::dark {

// Floquet multipliers and their classification as written (kind() as text).
struct FloquetRecord {
  std::vector<std::complex<double>> multipliers;
  std::string kind;
  double max_modulus = 0, max_real = 0, max_period_doubling = 0, max_oscillatory = 0;
  Index near_one = 0;
  double pairing_defect = 0, conjugation_defect = 0, log_det = 0;
};
FloquetRecord floquet_record(const sim::dark::FloquetResult& f);

struct DarkSolutionRecord {
  Params params;
  double omega_b = 0, omega_edge = 0;
  std::vector<double> x, y, x_seed, y_seed;  // Z(0) and the eq:xy_app seed on sites n = i - (N-1)/2
  std::vector<double> newton_residuals;
  sim::dark::DarkMeasures measures;
  std::optional<FloquetRecord> floquet;
};
// The record of a converged solution: z0 = (x(0), y(0)), the seed, Newton's residual history.
DarkSolutionRecord dark_solution_record(const Params& p, double omega_b, double omega_edge, const Eigen::VectorXd& z0,
                                        const Eigen::VectorXd& seed, const sim::dark::NewtonResult& newton,
                                        const sim::dark::DarkMeasures& measures, const sim::dark::FloquetResult* floquet);

struct DarkBranchRecord {
  Params params;
  Index sites = 0;
  std::vector<double> omega_b, tangent_omega, residual;
  std::vector<Index> iterations;  // written as int32
  std::vector<double> x, y;  // points x sites, row-major
  std::vector<sim::dark::DarkMeasures> measures;
  std::vector<FloquetRecord> floquet;  // one per point, or empty (not computed)
  std::vector<double> turning_points;
  std::string stop_reason;
};
DarkBranchRecord dark_branch_record(const Params& p, const sim::dark::BranchResult& branch, Index sites, bool floquet);

// The parts of the layout above that the model-file files share (jobs/dark/model_dark_hdf5.hpp),
// written into an open file: newton_residuals, group measures, group floquet (if any) of a
// solution; of a branch the per-point series (omega_b, tangent_omega, residual, iterations), then,
// after the profiles, the rest (turning_points, stop_reason, measures, floquet); b.x, b.y and
// b.params are not used. Without `second_strain` (a one-field or displacement-form lattice) the
// measures K_y, C_y are left out.
void write_solution_parts(Hdf5TreeFile& file, const std::vector<double>& newton_residuals, const sim::dark::DarkMeasures& measures,
                          const std::optional<FloquetRecord>& floquet, bool second_strain);
void write_branch_series(Hdf5TreeFile& file, const DarkBranchRecord& b);
void write_branch_parts(Hdf5TreeFile& file, const DarkBranchRecord& b, bool second_strain);

// Writers (temporary name + rename; InputError naming `path` if its directory is missing or it is a directory).
void write_dark_solution_hdf5(const std::filesystem::path& path, const DarkSolutionRecord& s);
void write_dark_branch_hdf5(const std::filesystem::path& path, const DarkBranchRecord& b);

}  // namespace lrchain::jobs::dark

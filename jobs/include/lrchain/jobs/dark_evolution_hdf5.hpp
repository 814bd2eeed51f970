#pragma once
// The HDF5 file of a dark breather's direct evolution (Figs. 21, 22, 25): `lrchain dark evolve
// --format hdf5` (OUT/result.h5 beside the CSV files) and Python's Evolution.to_hdf5 and
// ModelEvolution.to_hdf5 (the same file, one writer). Layout:
//   root attributes   lrchain_result ("Evolution" or "ModelEvolution"), lrchain_version,
//                     git_commit, model (JSON text); period (T_b), max_strain; a model file's edge as
//                     in jobs/model_dark_hdf5.hpp (branch, theta, ..., variables)
//   per period m = 1..M   datasets t (m T_b), E_b, C_x, K_x, position, depth (M)
//   stroboscopic profiles at t = m T_b, m = 0..M: the resonant chain's x, y (M+1 x sites); a
//                     model's z (M+1 x fields x sites) and n (sites)
#include <filesystem>
#include <vector>

#include "lrchain/jobs/dark_job.hpp"
#include "lrchain/jobs/model_dark_hdf5.hpp"
#include "lrchain/params.hpp"
#include "lrchain/sim/run_record.hpp"

namespace lrchain::jobs::dark {

struct DarkEvolutionRecord {
  double period = 0, max_strain = 0;
  sim::TimeSeries periods;       // t, E_b, C_x, K_x, position, depth: one row per period
  Index fields = 0, sites = 0;
  std::vector<double> profiles;  // (M+1) x fields x sites, row-major
};

// The record of an evolve job's result.
DarkEvolutionRecord dark_evolution_record(const DarkResult& r);

// Writers (temporary name + rename; InputError naming `path` if its directory is missing or it is not a regular file).
void write_dark_evolution_hdf5(const std::filesystem::path& path, const Params& params, const DarkEvolutionRecord& e);
void write_model_dark_evolution_hdf5(const std::filesystem::path& path, const ModelDarkEdgeRecord& edge,
                                     const DarkEvolutionRecord& e);

}  // namespace lrchain::jobs::dark

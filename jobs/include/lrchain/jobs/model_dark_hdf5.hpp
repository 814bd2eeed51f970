#pragma once
// The HDF5 files of the dark breathers of model files: `lrchain dark solve|floquet|continue --model
// FILE --format hdf5` (OUT/result.h5 beside the CSV files) and Python's ModelDarkSolution.to_hdf5
// and ModelBranch.to_hdf5 (the same file). The layout is the resonant chain's
// (sim/dark/dark_hdf5.hpp) with the profiles in the lattice's variables and the edge as attributes:
//   root attributes   lrchain_result ("ModelDarkSolution" or "ModelBranch"), lrchain_version,
//                     git_commit, model (JSON text: name, file_hash, parameters, and lattice_code where
//                     the front end reports it), branch, theta, omega_edge, curvature, h_tilde, lambda
//                     (left out without mean flow), lattice_form (strain | displacement), variables and
//                     one_sided_contacts (JSON lists of names)
//   a solution        attribute omega_b, contact_changes_per_period (left out for a smooth model);
//                     datasets n (sites), z and seed (fields x sites), newton_residuals; groups
//                     measures and floquet as the chain's (K_y, C_y left out where the lattice has no
//                     second strain-form variable)
//   a branch of P     datasets omega_b, tangent_omega, residual, iterations (P), n, z (P x fields x
//   points            sites), contact_changes_per_period (P, int64; left out for a smooth model),
//                     turning_points, attribute stop_reason, groups measures and floquet as the chain's
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "lrchain/jobs/dark_job.hpp"
#include "lrchain/jobs/dark_hdf5.hpp"

namespace lrchain::jobs::dark {

// The band edge, the lattice and the model of a model-file dark result.
struct ModelDarkEdgeRecord {
  nlohmann::json model;  // the summary's model object
  std::string branch;
  double theta = 0, omega_edge = 0, curvature = 0, h_tilde = 0;
  std::optional<double> lambda;  // none without mean flow
  std::string lattice_form;      // strain | displacement
  std::vector<std::string> variables, one_sided_contacts;
  Index sites = 0;
};

struct ModelDarkSolutionRecord {
  ModelDarkEdgeRecord edge;
  double omega_b = 0;
  std::vector<double> z, seed;  // fields x sites, field-major
  std::vector<double> newton_residuals;
  sim::dark::DarkMeasures measures;
  std::optional<jobs::dark::FloquetRecord> floquet;
  std::optional<Index> contact_changes_per_period;
};

struct ModelDarkBranchRecord {
  ModelDarkEdgeRecord edge;
  jobs::dark::DarkBranchRecord points;  // per point: omega_b, ..., measures, floquet (its x, y, params unused)
  std::vector<double> z;               // points x fields x sites
  std::vector<Index> contact_changes_per_period;  // per point; empty for a smooth model
  std::string parameter = "omega_b";   // the continued parameter (root attribute "parameter")
  std::vector<double> parameter_values;  // its value per point (dataset "parameter_values")
};

// The records of a model-file job's result `r` (its edge; solve/floquet; branch); `model` is the
// model object of its summary (to_json(r)["model"]).
ModelDarkEdgeRecord model_dark_edge_record(const DarkResult& r, const nlohmann::json& model);
ModelDarkSolutionRecord model_dark_solution_record(const DarkResult& r, const nlohmann::json& model);
ModelDarkBranchRecord model_dark_branch_record(const DarkResult& r, const nlohmann::json& model);

// The root of a model-file dark file in `file`: lrchain_result `result_class`, provenance, the edge
// attributes above and the dataset n.
void write_model_dark_root(jobs::Hdf5TreeFile& file, const char* result_class, const ModelDarkEdgeRecord& e);

// Writers (temporary name + rename; InputError naming `path` if its directory is missing or it is not a regular file).
void write_model_dark_solution_hdf5(const std::filesystem::path& path, const ModelDarkSolutionRecord& s);
void write_model_dark_branch_hdf5(const std::filesystem::path& path, const ModelDarkBranchRecord& b);

}  // namespace lrchain::jobs::dark

// HDF5 files of dark breathers and their branches (dark/dark_hdf5.hpp), shared by the CLI and Python.
#include "lrchain/jobs/dark_hdf5.hpp"

#include <cstdint>

#include <nlohmann/json.hpp>

#include "lrchain/model_json.hpp"
#include "lrchain/provenance_json.hpp"
#include "lrchain/jobs/hdf5_tree.hpp"
#include "lrchain/jobs/result_hdf5.hpp"

namespace lrchain::jobs::dark {

namespace {

void write_vector(Hdf5TreeFile& file, const std::string& path, const std::vector<double>& v) {
  file.write_dataset(path, Hdf5Element::float64, v.data(), {v.size()});
}

// The root attributes of a dark result: what it is, and its provenance and model.
void write_root(Hdf5TreeFile& file, const char* result_class, const Params& p) {
  file.write_attribute("/", "lrchain_result", std::string(result_class));
  write_provenance_attributes(file, {{"model", model_json(resonant_chain_model(p))}, {"provenance", lrchain::provenance_json()}});
}

const char* const measure_names[] = {"norm_squared", "K_x", "K_y", "C_x", "C_y", "E_b", "max_strain"};

// K_y and C_y: measures of the second strain-form variable (none in a one-field or displacement-form lattice).
bool second_strain_measure(std::size_t k) { return k == 2 || k == 4; }

double measure(const sim::dark::DarkMeasures& m, std::size_t k) {
  const double values[] = {m.norm_squared, m.K_x, m.K_y, m.C_x, m.C_y, m.E_b, m.max_strain};
  return values[k];
}

const char* const floquet_scalars[] = {"max_modulus", "max_real", "max_period_doubling", "max_oscillatory",
                                       "pairing_defect", "conjugation_defect", "log_det"};

double floquet_scalar(const FloquetRecord& f, std::size_t k) {
  const double values[] = {f.max_modulus, f.max_real, f.max_period_doubling, f.max_oscillatory,
                           f.pairing_defect, f.conjugation_defect, f.log_det};
  return values[k];
}

}  // namespace

FloquetRecord floquet_record(const sim::dark::FloquetResult& f) {
  return {f.multipliers, f.kind(), f.max_modulus, f.max_real, f.max_period_doubling, f.max_oscillatory,
          f.near_one, f.pairing_defect, f.conjugation_defect, f.log_det};
}

DarkSolutionRecord dark_solution_record(const Params& p, double omega_b, double omega_edge, const Eigen::VectorXd& z0,
                                        const Eigen::VectorXd& seed, const sim::dark::NewtonResult& newton,
                                        const sim::dark::DarkMeasures& measures, const sim::dark::FloquetResult* floquet) {
  DarkSolutionRecord r;
  r.params = p;
  r.omega_b = omega_b;
  r.omega_edge = omega_edge;
  const Eigen::Index N = z0.size() / 2;
  r.x.assign(z0.data(), z0.data() + N);
  r.y.assign(z0.data() + N, z0.data() + 2 * N);
  r.x_seed.assign(seed.data(), seed.data() + N);
  r.y_seed.assign(seed.data() + N, seed.data() + 2 * N);
  for (const auto& h : newton.history) r.newton_residuals.push_back(h.residual);
  r.measures = measures;
  if (floquet) r.floquet = floquet_record(*floquet);
  return r;
}

DarkBranchRecord dark_branch_record(const Params& p, const sim::dark::BranchResult& branch, Index sites, bool floquet) {
  DarkBranchRecord r;
  r.params = p;
  r.sites = sites;
  for (const sim::dark::BranchPoint& b : branch.points) {
    r.omega_b.push_back(b.omega_b);
    r.tangent_omega.push_back(b.tangent_omega);
    r.residual.push_back(b.residual);
    r.iterations.push_back(b.iterations);
    if (b.z0.size() == 2 * sites) {  // the resonant chain's x, y (a model's profiles are written as z)
      r.x.insert(r.x.end(), b.z0.data(), b.z0.data() + sites);
      r.y.insert(r.y.end(), b.z0.data() + sites, b.z0.data() + 2 * sites);
    }
    r.measures.push_back(b.measures);
    if (floquet) r.floquet.push_back(floquet_record(b.floquet));
  }
  r.turning_points = branch.turning_points;
  r.stop_reason = branch.stop_reason;
  return r;
}

void write_solution_parts(Hdf5TreeFile& file, const std::vector<double>& newton_residuals, const sim::dark::DarkMeasures& measures,
                          const std::optional<FloquetRecord>& floquet, bool second_strain) {
  write_vector(file, "/newton_residuals", newton_residuals);
  file.create_group("/measures");
  for (std::size_t k = 0; k < 7; ++k)
    if (second_strain || !second_strain_measure(k))
      file.write_attribute("/measures", measure_names[k], measure(measures, k));
  if (floquet) {
    const FloquetRecord& f = *floquet;
    file.create_group("/floquet");
    file.write_dataset("/floquet/multipliers", Hdf5Element::complex128, f.multipliers.data(), {f.multipliers.size()});
    file.write_attribute("/floquet", "kind", f.kind);
    for (std::size_t k = 0; k < 7; ++k) file.write_attribute("/floquet", floquet_scalars[k], floquet_scalar(f, k));
    file.write_attribute("/floquet", "near_one", std::int64_t(f.near_one));
  }
}

void write_branch_series(Hdf5TreeFile& file, const DarkBranchRecord& b) {
  write_vector(file, "/omega_b", b.omega_b);
  write_vector(file, "/tangent_omega", b.tangent_omega);
  write_vector(file, "/residual", b.residual);
  const std::vector<std::int32_t> iterations(b.iterations.begin(), b.iterations.end());
  file.write_dataset("/iterations", Hdf5Element::int32, iterations.data(), {b.omega_b.size()});
}

void write_branch_parts(Hdf5TreeFile& file, const DarkBranchRecord& b, bool second_strain) {
  const std::size_t points = b.omega_b.size();
  if (b.turning_points.empty()) file.write_attribute("/", "turning_points", std::string("[]"));
  else write_vector(file, "/turning_points", b.turning_points);
  file.write_attribute("/", "stop_reason", b.stop_reason);
  file.create_group("/measures");
  if (points > 0)
    for (std::size_t k = 0; k < 7; ++k) {
      if (!second_strain && second_strain_measure(k)) continue;
      std::vector<double> v;
      for (const auto& m : b.measures) v.push_back(measure(m, k));
      write_vector(file, std::string("/measures/") + measure_names[k], v);
    }
  if (!b.floquet.empty()) {
    file.create_group("/floquet");
    const std::size_t width = b.floquet.front().multipliers.size();
    std::vector<std::complex<double>> all;
    nlohmann::json kinds = nlohmann::json::array();
    std::vector<std::int64_t> near_one;
    for (const auto& f : b.floquet) {
      all.insert(all.end(), f.multipliers.begin(), f.multipliers.end());
      kinds.push_back(f.kind);
      near_one.push_back(f.near_one);
    }
    file.write_dataset("/floquet/multipliers", Hdf5Element::complex128, all.data(), {points, width});
    write_json_tree(file, "/floquet", {{"kind", kinds}});
    for (std::size_t k = 0; k < 7; ++k) {
      std::vector<double> v;
      for (const auto& f : b.floquet) v.push_back(floquet_scalar(f, k));
      write_vector(file, std::string("/floquet/") + floquet_scalars[k], v);
    }
    file.write_dataset("/floquet/near_one", Hdf5Element::int64, near_one.data(), {points});
  }
}

void write_dark_solution_hdf5(const std::filesystem::path& path, const DarkSolutionRecord& s) {
  Hdf5TreeFile file(path);
  write_root(file, "DarkSolution", s.params);
  file.write_attribute("/", "omega_b", s.omega_b);
  file.write_attribute("/", "omega_edge", s.omega_edge);
  std::vector<double> n(s.x.size());
  const Index sites = Index(n.size());
  for (Index i = 0; i < sites; ++i) n[std::size_t(i)] = double(i - (sites - 1) / 2);
  write_vector(file, "/n", n);
  write_vector(file, "/x", s.x);
  write_vector(file, "/y", s.y);
  write_vector(file, "/x_seed", s.x_seed);
  write_vector(file, "/y_seed", s.y_seed);
  write_solution_parts(file, s.newton_residuals, s.measures, s.floquet, true);
  file.commit();
}

void write_dark_branch_hdf5(const std::filesystem::path& path, const DarkBranchRecord& b) {
  Hdf5TreeFile file(path);
  write_root(file, "Branch", b.params);
  const std::size_t points = b.omega_b.size(), sites = std::size_t(b.sites);
  write_branch_series(file, b);
  file.write_dataset("/x", Hdf5Element::float64, b.x.data(), {points, sites});
  file.write_dataset("/y", Hdf5Element::float64, b.y.data(), {points, sites});
  write_branch_parts(file, b, true);
  file.commit();
}

}  // namespace lrchain::jobs::dark

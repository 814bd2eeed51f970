// The HDF5 files of model-file dark breathers and branches (model_dark_hdf5.hpp).
#include "lrchain/jobs/model_dark_hdf5.hpp"

#include <cstdint>

#include "lrchain/provenance_json.hpp"
#include "lrchain/jobs/hdf5_tree.hpp"
#include "lrchain/jobs/result_hdf5.hpp"

namespace lrchain::jobs::dark {

namespace {

using nlohmann::json;
using jobs::Hdf5Element;
using jobs::Hdf5TreeFile;

// K_y and C_y exist where the lattice has a second strain-form variable.
bool second_strain(const ModelDarkEdgeRecord& e) { return e.lattice_form == "strain" && e.variables.size() >= 2; }

}  // namespace

ModelDarkEdgeRecord model_dark_edge_record(const DarkResult& r, const json& model) {
  const DarkEdge& e = r.edge;
  ModelDarkEdgeRecord edge;
  edge.model = model;
  edge.branch = e.branch;
  edge.theta = e.theta;
  edge.omega_edge = e.omega;
  edge.curvature = e.curvature;
  edge.h_tilde = e.h_tilde;
  if (e.mean_flow) edge.lambda = e.lambda;
  edge.lattice_form = e.mean_flow ? "strain" : "displacement";
  edge.variables = e.variables;
  edge.one_sided_contacts = e.one_sided_contacts;
  edge.sites = dark_sites(r.config);
  return edge;
}

void write_model_dark_root(Hdf5TreeFile& file, const char* result_class, const ModelDarkEdgeRecord& e) {
  file.write_attribute("/", "lrchain_result", std::string(result_class));
  jobs::write_provenance_attributes(file, {{"model", e.model}, {"provenance", provenance_json()}});
  jobs::write_json_tree(file, "", {{"branch", e.branch},
                                  {"theta", e.theta},
                                  {"omega_edge", e.omega_edge},
                                  {"curvature", e.curvature},
                                  {"h_tilde", e.h_tilde},
                                  {"lambda", e.lambda ? json(*e.lambda) : json(nullptr)},
                                  {"lattice_form", e.lattice_form},
                                  {"variables", e.variables},
                                  {"one_sided_contacts", e.one_sided_contacts}});
  std::vector<double> n(std::size_t(e.sites));
  for (Index i = 0; i < e.sites; ++i) n[std::size_t(i)] = double(i - (e.sites - 1) / 2);
  file.write_dataset("/n", Hdf5Element::float64, n.data(), {n.size()});
}

ModelDarkSolutionRecord model_dark_solution_record(const DarkResult& r, const json& model) {
  ModelDarkSolutionRecord s;
  s.edge = model_dark_edge_record(r, model);
  s.omega_b = r.config.omega_b;
  s.z.assign(r.z0.data(), r.z0.data() + r.z0.size());
  s.seed.assign(r.seed.data(), r.seed.data() + r.seed.size());
  for (const auto& h : r.newton.history) s.newton_residuals.push_back(h.residual);
  s.measures = r.measures;
  if (r.floquet) s.floquet = jobs::dark::floquet_record(*r.floquet);
  s.contact_changes_per_period = r.contact_changes_per_period;
  return s;
}

ModelDarkBranchRecord model_dark_branch_record(const DarkResult& r, const json& model) {
  ModelDarkBranchRecord b;
  b.edge = model_dark_edge_record(r, model);
  b.points = jobs::dark::dark_branch_record(Params{}, r.branch, dark_sites(r.config), r.config.branch_floquet);
  for (const auto& p : r.branch.points) {
    b.z.insert(b.z.end(), p.z0.data(), p.z0.data() + p.z0.size());
    if (p.contact_changes_per_period) b.contact_changes_per_period.push_back(*p.contact_changes_per_period);
  }
  if (b.contact_changes_per_period.size() != r.branch.points.size()) b.contact_changes_per_period.clear();
  b.parameter = r.config.parameter;
  for (const auto& p : r.branch.points) b.parameter_values.push_back(p.parameter);
  return b;
}

void write_model_dark_solution_hdf5(const std::filesystem::path& path, const ModelDarkSolutionRecord& s) {
  Hdf5TreeFile file(path);
  write_model_dark_root(file, "ModelDarkSolution", s.edge);
  file.write_attribute("/", "omega_b", s.omega_b);
  if (s.contact_changes_per_period)
    file.write_attribute("/", "contact_changes_per_period", std::int64_t(*s.contact_changes_per_period));
  const std::size_t fields = s.edge.variables.size(), sites = std::size_t(s.edge.sites);
  file.write_dataset("/z", Hdf5Element::float64, s.z.data(), {fields, sites});
  file.write_dataset("/seed", Hdf5Element::float64, s.seed.data(), {fields, sites});
  jobs::dark::write_solution_parts(file, s.newton_residuals, s.measures, s.floquet, second_strain(s.edge));
  file.commit();
}

void write_model_dark_branch_hdf5(const std::filesystem::path& path, const ModelDarkBranchRecord& b) {
  Hdf5TreeFile file(path);
  write_model_dark_root(file, "ModelBranch", b.edge);
  jobs::dark::write_branch_series(file, b.points);
  const std::size_t points = b.points.omega_b.size(), fields = b.edge.variables.size(), sites = std::size_t(b.edge.sites);
  file.write_dataset("/z", Hdf5Element::float64, b.z.data(), {points, fields, sites});
  if (!b.contact_changes_per_period.empty()) {
    const std::vector<std::int64_t> counts(b.contact_changes_per_period.begin(), b.contact_changes_per_period.end());
    file.write_dataset("/contact_changes_per_period", Hdf5Element::int64, counts.data(), {points});
  }
  file.write_attribute("/", "parameter", b.parameter);
  file.write_dataset("/parameter_values", Hdf5Element::float64, b.parameter_values.data(), {b.parameter_values.size()});
  jobs::dark::write_branch_parts(file, b.points, second_strain(b.edge));
  file.commit();
}

}  // namespace lrchain::jobs::dark

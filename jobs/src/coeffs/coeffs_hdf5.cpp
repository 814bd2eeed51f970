// The HDF5 file of NLS coefficients (lrchain/jobs/coeffs_hdf5.hpp).
#include "lrchain/jobs/coeffs_hdf5.hpp"

#include <limits>

#include "lrchain/jobs/output_lock.hpp"
#include "lrchain/model_json.hpp"
#include "lrchain/provenance_json.hpp"
#include "lrchain/jobs/hdf5_tree.hpp"
#include "lrchain/jobs/result_hdf5.hpp"

namespace lrchain::jobs {

namespace {

using jobs::Hdf5Element;

// The record of `rows` (one branch) at their wavenumbers; `shape` empty for one wavenumber.
CoefficientsRecord record_of(const nlohmann::json& model, const std::string& branch,
                             const std::vector<NlsCoefficients>& rows, std::vector<std::size_t> shape) {
  CoefficientsRecord r;
  r.model = model;
  r.branch = branch;
  r.shape = std::move(shape);
  for (const std::string& name : coefficient_column_names()) r.columns.push_back({name, {}});
  for (const NlsCoefficients& c : rows) {
    r.theta.push_back(c.theta);
    const double values[] = {c.omega, c.group_velocity, c.curvature, c.gamma, c.beta, c.h, c.lambda, c.h_tilde,
                             c.nonresonance1, c.nonresonance2};
    for (std::size_t k = 0; k < r.columns.size(); ++k) r.columns[k].second.push_back(values[k]);
    r.regime_code.push_back(std::int8_t(c.regime));
  }
  return r;
}

}  // namespace

const std::vector<std::string>& coefficient_column_names() {
  static const std::vector<std::string> names{"omega", "group_velocity", "curvature", "gamma", "beta", "h",
                                              "lambda", "h_tilde", "nonresonance1", "nonresonance2"};
  return names;
}

std::vector<CoefficientsRecord> coefficients_records(const CoeffsResult& result) {
  const nlohmann::json model = model_json(result.model);
  if (!result.is_table) return {record_of(model, result.branch, {result.coefficients}, {})};
  std::vector<CoefficientsRecord> records;
  for (const CoeffsTableBranch& branch : result.table) {
    CoefficientsRecord r = record_of(model, branch.name, branch.rows, {branch.rows.size()});
    if (!branch.mean_flow)  // an on-site model has no lambda (the JSON's null)
      for (auto& [name, values] : r.columns)
        if (name == "lambda") values.assign(values.size(), std::numeric_limits<double>::quiet_NaN());
    records.push_back(std::move(r));
  }
  return records;
}

void write_coefficients_hdf5(const std::filesystem::path& path, const CoefficientsRecord& r) {
  jobs::Hdf5TreeFile file(path);
  file.write_attribute("/", "lrchain_result", std::string("Coefficients"));
  jobs::write_provenance_attributes(file, {{"model", r.model}, {"provenance", provenance_json()}});
  file.write_attribute("/", "branch", r.branch);
  file.write_dataset("/theta", Hdf5Element::float64, r.theta.data(), r.shape);
  for (const auto& [name, values] : r.columns) file.write_dataset("/" + name, Hdf5Element::float64, values.data(), r.shape);
  file.write_dataset("/regime_code", Hdf5Element::int8, r.regime_code.data(), r.shape);
  file.write_attribute("/regime_code", "flag_meanings", std::string("focusing defocusing degenerate singular"));
  file.commit();
}

std::vector<std::string> write(const CoeffsResult& result, const std::filesystem::path& out) {
  const OutputLock lock(out);
  std::vector<std::string> files;
  for (const CoefficientsRecord& r : coefficients_records(result)) {
    files.push_back(result.is_table ? "result_" + r.branch + ".h5" : "result.h5");
    write_coefficients_hdf5(out / files.back(), r);
  }
  return files;
}

}  // namespace lrchain::jobs

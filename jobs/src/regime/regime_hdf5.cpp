// The HDF5 files of the regime jobs (lrchain/jobs/regime_hdf5.hpp).
#include "lrchain/jobs/regime_hdf5.hpp"

#include <initializer_list>
#include <utility>

#include "lrchain/jobs/output_lock.hpp"
#include "lrchain/provenance_json.hpp"
#include "lrchain/jobs/hdf5_tree.hpp"
#include "lrchain/jobs/result_hdf5.hpp"

namespace lrchain::jobs {

namespace {

using jobs::Hdf5Element;
using jobs::Hdf5TreeFile;

// lrchain_result, the provenance attributes, the branch and the result's other text attributes `texts`.
void write_root(Hdf5TreeFile& file, const char* result_class, const nlohmann::json& model, const std::string& branch,
                std::initializer_list<std::pair<const char*, std::string>> texts = {}) {
  file.write_attribute("/", "lrchain_result", std::string(result_class));
  jobs::write_provenance_attributes(file, {{"model", model}, {"provenance", provenance_json()}});
  file.write_attribute("/", "branch", branch);
  for (const auto& [name, text] : texts) file.write_attribute("/", name, text);
}

void write_vector(Hdf5TreeFile& file, const std::string& path, const std::vector<double>& v) {
  file.write_dataset(path, Hdf5Element::float64, v.data(), {v.size()});
}

// A curve's cause and points in `group` ("" for the root).
void write_curve(Hdf5TreeFile& file, const std::string& group, const CurveRecord& c) {
  file.write_attribute(group.empty() ? "/" : group, "cause", c.cause);
  file.write_dataset(group + "/points", Hdf5Element::float64, c.points.data(), {c.points.size() / 2, 2});
}

std::vector<double> axis_values(const regime::GridAxis& a) {
  std::vector<double> v(std::size_t(a.n));
  for (Index i = 0; i < a.n; ++i) v[std::size_t(i)] = a.at(i);
  return v;
}

}  // namespace

IntervalsRecord intervals_record(const RegimeIntervalsResult& result) {
  IntervalsRecord r;
  r.model = result.model;
  r.branch = result.branch;
  for (const regime::FocusingInterval& i : result.structure.intervals) {
    r.lo.push_back(i.lo);
    r.hi.push_back(i.hi);
    r.lo_cause.emplace_back(to_string(i.lo_cause));
    r.hi_cause.emplace_back(to_string(i.hi_cause));
  }
  for (const regime::BoundaryRoot& root : result.structure.roots) {
    r.roots.push_back(root.theta);
    r.root_cause.emplace_back(to_string(root.cause));
  }
  return r;
}

CurveRecord curve_record(const regime::BoundaryCurve& curve) {
  CurveRecord c{std::string(to_string(curve.cause)), {}};
  for (const auto& p : curve.points) c.points.insert(c.points.end(), {p.x, p.y});
  return c;
}

std::vector<RegimeMapRecord> regime_map_records(const RegimeMapResult& result) {
  std::vector<RegimeMapRecord> records;
  for (const RegimeMapPanel& panel : result.panels) {
    RegimeMapRecord r;
    r.model = result.model;
    r.branch = panel.branch;
    r.plane = result.plane;
    r.x_name = result.axis;
    r.y_name = result.plane == "delta0-omega" ? "omega" : "theta";
    r.x = axis_values(panel.x);
    r.y = axis_values(panel.y);
    r.values = panel.values;
    for (const regime::BoundaryCurve& curve : panel.curves) r.curves.push_back(curve_record(curve));
    records.push_back(std::move(r));
  }
  return records;
}

void write_intervals_hdf5(const std::filesystem::path& path, const IntervalsRecord& r) {
  Hdf5TreeFile file(path);
  write_root(file, "Intervals", r.model, r.branch,
             {{"lo_cause", nlohmann::json(r.lo_cause).dump()}, {"hi_cause", nlohmann::json(r.hi_cause).dump()},
              {"root_cause", nlohmann::json(r.root_cause).dump()}});
  write_vector(file, "/lo", r.lo);
  write_vector(file, "/hi", r.hi);
  write_vector(file, "/roots", r.roots);
  file.commit();
}

void write_regime_map_hdf5(const std::filesystem::path& path, const RegimeMapRecord& r) {
  Hdf5TreeFile file(path);
  write_root(file, "RegimeMap", r.model, r.branch, {{"plane", r.plane}, {"x_name", r.x_name}, {"y_name", r.y_name}});
  write_vector(file, "/x", r.x);
  write_vector(file, "/y", r.y);
  file.write_dataset("/values", Hdf5Element::int8, r.values.data(), {r.y.size(), r.x.size()});
  file.write_attribute("/values", "flag_meanings", std::string("-1 outside_band, 0 defocusing, 1 focusing, 2 singular"));
  file.create_group("/curves");
  for (std::size_t k = 0; k < r.curves.size(); ++k) {
    const std::string group = "/curves/" + std::to_string(k);
    file.create_group(group);
    write_curve(file, group, r.curves[k]);
  }
  file.commit();
}

void write_boundary_curve_hdf5(const std::filesystem::path& path, const BoundaryCurveRecord& r) {
  Hdf5TreeFile file(path);
  write_root(file, "BoundaryCurve", r.model, r.branch, {{"axis", r.axis}, {"y_name", r.y_name}});
  write_curve(file, "", r.curve);
  file.commit();
}

std::vector<std::string> write_hdf5(const RegimeIntervalsResult& result, const std::filesystem::path& out) {
  const OutputLock lock(out);
  write_intervals_hdf5(out / "result.h5", intervals_record(result));
  return {"result.h5"};
}

std::vector<std::string> write_hdf5(const RegimeMapResult& result, const std::filesystem::path& out) {
  const std::vector<RegimeMapRecord> records = regime_map_records(result);
  std::vector<std::string> files;
  for (const RegimeMapRecord& r : records) {
    files.push_back(records.size() == 1 ? "result.h5" : "result_" + r.branch + ".h5");
    write_regime_map_hdf5(out / files.back(), r);
  }
  return files;
}

}  // namespace lrchain::jobs

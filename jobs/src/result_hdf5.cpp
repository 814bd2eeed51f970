// HDF5 files of simulation results, shared by the CLI (--format hdf5) and Python's to_hdf5()
// (result_hdf5.hpp).
#include "lrchain/jobs/result_hdf5.hpp"

#include <cstdint>

#include "lrchain/errors.hpp"
#include "lrchain/jobs/hdf5_tree.hpp"
#include "lrchain/jobs/output_files.hpp"
#include "lrchain/version.hpp"

namespace lrchain::jobs {

namespace {

using json = nlohmann::json;

// The result class name (Python's) and the file names of the series columns of a kind.
RecordLayout layout_of(SimulationKind kind) {
  switch (kind) {
    case SimulationKind::bright: return {"BrightResult", {{"X", "centre"}}};
    case SimulationKind::drive: return {"DriveResult", {}};
    case SimulationKind::modulated: return {"ModulatedResult", {}};
  }
  return {"", {}};
}

// A JSON list of numbers is a dataset (int64 when every entry is an integer, else float64); an
// empty list or one of strings is a JSON-text attribute; other lists are groups "0", "1", ...
bool all_numbers(const json& a) {
  for (const auto& v : a)
    if (!v.is_number()) return false;
  return !a.empty();
}

bool all_strings(const json& a) {
  for (const auto& v : a)
    if (!v.is_string()) return false;
  return true;
}

// JSON text of a list of strings as Python's json.dumps writes it: ", " between items, non-ASCII escaped.
std::string python_json_list(const json& a) {
  std::string text = "[";
  for (std::size_t i = 0; i < a.size(); ++i) text += (i ? ", " : "") + a[i].dump(-1, ' ', true);
  return text + "]";
}

void write_json_value(Hdf5TreeFile& file, const std::string& group, const std::string& name, const json& v) {
  const std::string object = group.empty() ? "/" : group;
  const std::string path = group + "/" + name;
  if (v.is_null()) return;
  if (v.is_object()) {
    file.create_group(path);
    write_json_tree(file, path, v);
  } else if (v.is_boolean()) {
    file.write_attribute(object, name, std::int64_t(v.get<bool>() ? 1 : 0));
  } else if (v.is_number_integer()) {
    file.write_attribute(object, name, v.get<std::int64_t>());
  } else if (v.is_number()) {
    file.write_attribute(object, name, v.get<double>());
  } else if (v.is_string()) {
    file.write_attribute(object, name, v.get<std::string>());
  } else if (all_numbers(v)) {
    bool integers = true;
    for (const auto& x : v) integers = integers && x.is_number_integer();
    if (integers) {
      std::vector<std::int64_t> data;
      for (const auto& x : v) data.push_back(x.get<std::int64_t>());
      file.write_dataset(path, Hdf5Element::int64, data.data(), {data.size()});
    } else {
      std::vector<double> data;
      for (const auto& x : v) data.push_back(x.get<double>());
      file.write_dataset(path, Hdf5Element::float64, data.data(), {data.size()});
    }
  } else if (all_strings(v)) {
    file.write_attribute(object, name, python_json_list(v));
  } else {
    file.create_group(path);
    for (std::size_t i = 0; i < v.size(); ++i) write_json_value(file, path, std::to_string(i), v[i]);
  }
}

// A group with a field's sites n, times t and values (times x sites), and its quantity.
template <class Value>
void write_field(Hdf5TreeFile& file, const std::string& path, const std::string& quantity, const std::vector<double>& n,
                 const std::vector<double>& t, const std::vector<Value>& values, Hdf5Element element) {
  file.create_group(path);
  file.write_attribute(path, "quantity", quantity);
  file.write_dataset(path + "/n", Hdf5Element::float64, n.data(), {n.size()});
  file.write_dataset(path + "/t", Hdf5Element::float64, t.data(), {t.size()});
  file.write_dataset(path + "/values", element, values.data(), {t.size(), n.size()});
}

void write_record(Hdf5TreeFile& file, const sim::RunRecord& record, const RecordLayout& layout) {
  write_series_datasets(file, record.series, layout.renamed);
  if (!record.fields.empty()) {
    const sim::SpaceTime& f = record.fields[0];
    std::vector<double> n(f.sites);
    for (Index i = 0; i < f.sites; ++i) n[static_cast<std::size_t>(i)] = double(f.first_label + i);
    write_field(file, "/energy_density", f.quantity, n, f.times, f.values, Hdf5Element::float32);
  }
  file.create_group("/snapshots");
  for (std::size_t k = 0; k < record.snapshots.size(); ++k) {
    const sim::Snapshot& s = record.snapshots[k];
    const std::string group = "/snapshots/" + std::to_string(k);
    file.create_group(group);
    file.write_attribute(group, "t", s.t);
    file.write_attribute(group, "tag", s.tag);
    file.create_group(group + "/columns");
    const std::size_t width = s.names.size(), length = width ? s.data.size() / width : 0;
    std::vector<double> values(length);
    for (std::size_t c = 0; c < width; ++c) {
      for (std::size_t r = 0; r < length; ++r) values[r] = s.data[r * width + c];
      file.write_dataset(group + "/columns/" + s.names[c], Hdf5Element::float64, values.data(), {length});
    }
  }
}

// Writes OUT/result.h5 and OUT/summary.json of a CLI run.
std::vector<std::string> write_outputs(const std::filesystem::path& dir, SimulationKind kind, const sim::RunRecord& record,
                                       const json& summary) {
  write_simulation_hdf5(dir / "result.h5", kind, record, summary);
  write_file_atomic(dir, "summary.json", summary.dump(2) + "\n");
  return {};
}

}  // namespace

SimulationKind simulation_kind(const std::string& name) {
  if (name == "bright") return SimulationKind::bright;
  if (name == "drive") return SimulationKind::drive;
  if (name == "modulated") return SimulationKind::modulated;
  throw InputError("result kind '" + name + "': bright, drive or modulated");
}

void write_series_datasets(Hdf5TreeFile& file, const sim::TimeSeries& series,
                           const std::vector<std::pair<std::string, std::string>>& renamed) {
  const std::size_t rows = series.rows(), cols = series.names.size();
  std::vector<double> column(rows);
  for (std::size_t c = 0; c < cols; ++c) {
    std::string name = series.names[c];
    for (const auto& [from, to] : renamed)
      if (name == from) name = to;
    for (std::size_t r = 0; r < rows; ++r) column[r] = series.at(r, c);
    file.write_dataset("/" + name, Hdf5Element::float64, column.data(), {rows});
  }
}

void write_json_tree(Hdf5TreeFile& file, const std::string& group, const json& j) {
  for (const auto& [name, value] : j.items()) write_json_value(file, group, name, value);
}

void write_provenance_attributes(Hdf5TreeFile& file, const json& summary) {
  file.write_attribute("/", "lrchain_version", std::string(LRCHAIN_VERSION_STRING));
  const json provenance = summary.value("provenance", json::object());
  const json commit = provenance.value("git_commit", json(nullptr));
  file.write_attribute("/", "git_commit", commit.is_string() ? commit.get<std::string>() : std::string("unknown"));
  file.write_attribute("/", "model", summary.value("model", json(nullptr)).dump());
}

void write_simulation_tree(Hdf5TreeFile& file, const RecordLayout& layout, const sim::RunRecord& record,
                           const json& summary) {
  file.write_attribute("/", "lrchain_result", layout.result_class);
  write_provenance_attributes(file, summary);
  write_record(file, record, layout);
  file.create_group("/summary");
  write_json_tree(file, "/summary", summary);
}

void write_simulation_hdf5(const std::filesystem::path& path, SimulationKind kind, const sim::RunRecord& record,
                           const json& summary, const std::vector<SampledField>& extra) {
  Hdf5TreeFile file(path);
  write_simulation_tree(file, layout_of(kind), record, summary);
  for (const SampledField& f : extra) write_field(file, "/" + f.name, f.quantity, f.n, f.t, f.values, Hdf5Element::float64);
  file.commit();
}

std::vector<std::string> write_hdf5_outputs(const std::filesystem::path& dir, const sim::BrightRunResult& r,
                                            const json& summary) {
  return write_outputs(dir, SimulationKind::bright, r.record, summary);
}

std::vector<std::string> write_hdf5_outputs(const std::filesystem::path& dir, const sim::DriveRunResult& r,
                                            const json& summary) {
  return write_outputs(dir, SimulationKind::drive, r.record, summary);
}

std::vector<std::string> write_hdf5_outputs(const std::filesystem::path& dir, const sim::ModulatedRunResult& r,
                                            const json& summary) {
  return write_outputs(dir, SimulationKind::modulated, r.record, summary);
}

}  // namespace lrchain::jobs

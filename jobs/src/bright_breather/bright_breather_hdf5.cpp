// The HDF5 file of an exact bright breather or branch (lrchain/jobs/bright_breather_hdf5.hpp).
#include "lrchain/jobs/bright_breather_hdf5.hpp"

#include <complex>

#include "lrchain/jobs/hdf5_tree.hpp"
#include "lrchain/jobs/result_hdf5.hpp"

namespace lrchain::jobs::bright_breather {

using nlohmann::json;
using jobs::Hdf5Element;

BrightBreatherRecord bright_breather_record(const BrightBreatherResult& r) {
  BrightBreatherRecord b;
  b.summary = to_json(r);
  b.variables = r.edge.variables;
  b.sites = r.config.sites;
  b.z.assign(r.z0.data(), r.z0.data() + r.z0.size());
  b.seed.assign(r.seed.data(), r.seed.data() + r.seed.size());
  b.branch = r.config.step == BrightStep::branch;
  for (const auto& p : r.branch.points) b.branch_z.insert(b.branch_z.end(), p.z0.data(), p.z0.data() + p.z0.size());
  b.evolution = r.evolution.has_value();
  if (b.evolution) {
    const bool energy = r.evolution->has_energy;
    b.periods.names = energy ? std::vector<std::string>{"t", "deviation", "energy"} : std::vector<std::string>{"t", "deviation"};
    for (const auto& m : r.evolution->samples) {
      b.periods.data.insert(b.periods.data.end(), {m.t, m.deviation});
      if (energy) b.periods.data.push_back(m.energy);
    }
  }
  return b;
}

void write_bright_breather_hdf5(const std::filesystem::path& path, const BrightBreatherRecord& b) {
  jobs::Hdf5TreeFile file(path);
  const json& s = b.summary;
  file.write_attribute("/", "lrchain_result",
                       std::string(b.branch ? "BrightBranch" : b.evolution ? "BrightEvolution" : "BrightBreather"));
  jobs::write_provenance_attributes(file, s);
  file.write_attribute("/", "omega_b", s.at("omega_b").get<double>());
  file.write_attribute("/", "center", s.at("center").get<std::string>());
  file.write_attribute("/", "variables", json(b.variables).dump());
  file.write_attribute("/", "summary_json", s.dump());
  const std::size_t fields = b.variables.size(), sites = std::size_t(b.sites);
  std::vector<double> n(sites);
  for (std::size_t i = 0; i < sites; ++i) n[i] = double(Index(i) - (b.sites - 1) / 2);
  file.write_dataset("/n", Hdf5Element::float64, n.data(), {sites});
  file.write_dataset("/z", Hdf5Element::float64, b.z.data(), {fields, sites});
  file.write_dataset("/seed", Hdf5Element::float64, b.seed.data(), {fields, sites});
  if (b.branch)
    file.write_dataset("/branch_z", Hdf5Element::float64, b.branch_z.data(),
                       {fields && sites ? b.branch_z.size() / (fields * sites) : 0, fields, sites});
  if (s.contains("floquet") && s["floquet"].is_object()) {
    std::vector<std::complex<double>> m;
    for (const json& pair : s["floquet"].at("multipliers")) m.emplace_back(pair.at(0).get<double>(), pair.at(1).get<double>());
    file.write_dataset("/floquet_multipliers", Hdf5Element::complex128, m.data(), {m.size()});
  }
  if (b.evolution) jobs::write_series_datasets(file, b.periods);
  file.create_group("/summary");
  jobs::write_json_tree(file, "/summary", s);
  file.commit();
}

}  // namespace lrchain::jobs::bright_breather

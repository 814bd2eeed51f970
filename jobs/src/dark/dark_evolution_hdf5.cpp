// The HDF5 file of a dark breather's evolution (dark_evolution_hdf5.hpp).
#include "lrchain/jobs/dark_evolution_hdf5.hpp"

#include "lrchain/model_json.hpp"
#include "lrchain/provenance_json.hpp"
#include "lrchain/jobs/hdf5_tree.hpp"
#include "lrchain/jobs/result_hdf5.hpp"

namespace lrchain::jobs::dark {

namespace {

using jobs::Hdf5Element;

// period, max_strain and the per-period series.
void write_periods(jobs::Hdf5TreeFile& file, const DarkEvolutionRecord& e) {
  file.write_attribute("/", "period", e.period);
  file.write_attribute("/", "max_strain", e.max_strain);
  jobs::write_series_datasets(file, e.periods);
}

}  // namespace

DarkEvolutionRecord dark_evolution_record(const DarkResult& r) {
  const sim::dark::DarkEvolution& evolution = r.evolution;
  DarkEvolutionRecord e;
  e.period = evolution.period;
  e.max_strain = evolution.max_strain;
  e.periods.names = {"t", "E_b", "C_x", "K_x", "position", "depth"};
  for (const auto& p : evolution.periods) e.periods.data.insert(e.periods.data.end(), {p.t, p.E_b, p.C_x, p.K_x, p.position, p.depth});
  e.fields = r.edge.fields;
  e.sites = evolution.sites;
  for (const auto& z : evolution.snapshots) e.profiles.insert(e.profiles.end(), z.data(), z.data() + z.size());
  return e;
}

void write_dark_evolution_hdf5(const std::filesystem::path& path, const Params& params, const DarkEvolutionRecord& e) {
  jobs::Hdf5TreeFile file(path);
  file.write_attribute("/", "lrchain_result", std::string("Evolution"));
  jobs::write_provenance_attributes(file, {{"model", model_json(resonant_chain_model(params))},
                                          {"provenance", provenance_json()}});
  write_periods(file, e);
  // The chain's two strains x, y apart: (M+1) x sites each.
  const std::size_t sites = std::size_t(e.sites), rows = sites ? e.profiles.size() / (2 * sites) : 0;
  std::vector<double> x, y;
  for (std::size_t m = 0; m < rows; ++m) {
    const double* row = e.profiles.data() + m * 2 * sites;
    x.insert(x.end(), row, row + sites);
    y.insert(y.end(), row + sites, row + 2 * sites);
  }
  file.write_dataset("/x", Hdf5Element::float64, x.data(), {rows, sites});
  file.write_dataset("/y", Hdf5Element::float64, y.data(), {rows, sites});
  file.commit();
}

void write_model_dark_evolution_hdf5(const std::filesystem::path& path, const ModelDarkEdgeRecord& edge,
                                     const DarkEvolutionRecord& e) {
  jobs::Hdf5TreeFile file(path);
  write_model_dark_root(file, "ModelEvolution", edge);
  write_periods(file, e);
  const std::size_t fields = std::size_t(e.fields), sites = std::size_t(e.sites);
  const std::size_t rows = fields > 0 && sites > 0 ? e.profiles.size() / (fields * sites) : 0;
  file.write_dataset("/z", Hdf5Element::float64, e.profiles.data(), {rows, fields, sites});
  file.commit();
}

}  // namespace lrchain::jobs::dark

// The HDF5 file of a ring run (model_run_hdf5.hpp).
#include <limits>

#include "lrchain/jobs/simulate/model_run_hdf5.hpp"
#include "lrchain/jobs/hdf5_tree.hpp"
#include "lrchain/jobs/output_files.hpp"
#include "lrchain/jobs/result_hdf5.hpp"

namespace lrchain::jobs {

sim::TimeSeries ring_amplitude_table(const sim::RingRunResult& r) {
  sim::TimeSeries table;
  table.names = {"amplitude",       "measured_frequency", "predicted_frequency",
                 "measured_shift",  "predicted_shift",    "relative_disagreement"};
  for (const sim::RingAmplitude& a : r.amplitudes)
    table.data.insert(table.data.end(),
                      {a.amplitude, a.measured_frequency, a.predicted_frequency, a.measured_shift, a.predicted_shift,
                       a.relative_disagreement.value_or(std::numeric_limits<double>::quiet_NaN())});
  return table;
}

void write_ring_hdf5(const std::filesystem::path& path, const sim::RunRecord& record, const sim::TimeSeries& amplitudes,
                     const nlohmann::json& summary) {
  jobs::Hdf5TreeFile file(path);
  jobs::write_simulation_tree(file, {"RingResult", {{"t", "packet_t"}}}, record, summary);
  jobs::write_series_datasets(file, amplitudes);
  file.commit();
}

std::vector<std::string> write_hdf5_outputs(const std::filesystem::path& dir, const sim::RingRunResult& r,
                                            const nlohmann::json& summary) {
  jobs::ensure_directory(dir);
  write_ring_hdf5(dir / "result.h5", r.record, ring_amplitude_table(r), summary);
  jobs::write_file_atomic(dir, "summary.json", summary.dump(2) + "\n");
  return {};
}

}  // namespace lrchain::jobs

// The HDF5 file of a model bright-breather run (model_run_hdf5.hpp).
#include "lrchain/jobs/simulate/model_run_hdf5.hpp"

#include "lrchain/jobs/hdf5_tree.hpp"
#include "lrchain/jobs/output_files.hpp"
#include "lrchain/jobs/result_hdf5.hpp"

namespace lrchain::jobs {

void write_model_bright_hdf5(const std::filesystem::path& path, const sim::RunRecord& record,
                             const nlohmann::json& summary) {
  jobs::Hdf5TreeFile file(path);
  jobs::write_simulation_tree(file, {"ModelBrightResult", {{"X", "centre"}}}, record, summary);
  file.commit();
}

std::vector<std::string> write_hdf5_outputs(const std::filesystem::path& dir, const sim::ModelBrightResult& r,
                                            const nlohmann::json& summary) {
  jobs::ensure_directory(dir);
  write_model_bright_hdf5(dir / "result.h5", r.record, summary);
  jobs::write_file_atomic(dir, "summary.json", summary.dump(2) + "\n");
  return {};
}

}  // namespace lrchain::jobs

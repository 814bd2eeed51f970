// Loading a sweep's model file without a compiler: shipped model files only (sweep/model_file.hpp).
#include "lrchain/jobs/sweep/model_file.hpp"

#include "lrchain/errors.hpp"
#include "lrchain/sim/model_lattice_bloch.hpp"

namespace lrchain::jobs::sweep {

ModelFile load_shipped_model_file(const std::string& path) {
  const ModelDefinition* shipped = find_shipped_model_by_bytes(read_model_file_bytes(path));
  if (shipped == nullptr)
    throw InputError(path + ": not a shipped model file, and no model compiler was given to this sweep (run it with "
                            "`lrchain sweep`, which compiles model files)");
  ModelFile f;
  f.path = path;
  // Shipped definitions and kernels live for the whole program: shared without owning.
  f.definition = std::shared_ptr<const ModelDefinition>(std::shared_ptr<const ModelDefinition>(), shipped);
  const lrchain_lattice_kernels* kernels = sim::compiled_in_lattice_kernels(Model(f.definition));
  if (kernels == nullptr) throw InputError(path + ": the shipped model " + shipped->name + " has no compiled-in lattice code");
  f.kernels = std::shared_ptr<const lrchain_lattice_kernels>(std::shared_ptr<const lrchain_lattice_kernels>(), kernels);
  return f;
}

}  // namespace lrchain::jobs::sweep

#pragma once
// One HDF5 file of groups, n-dimensional datasets and scalar attributes, written through the HDF5 C
// library (Debian libhdf5-dev) to a temporary name and renamed into place on commit(): the format
// of `result.to_hdf5(path)` in the Python module, read back with h5py. Complex datasets are stored
// as the compound {r, i} that h5py reads as complex numbers.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace lrchain::jobs {

enum class Hdf5Element { float64, float32, int64, int32, int8, complex128 };

class Hdf5TreeFile {
 public:
  // Throws InputError naming `path` if its directory does not exist or `path` exists and is not a
  // regular file (check_output_target: a directory, device, FIFO or socket is never replaced);
  // nothing is created before commit() but the temporary file next to it.
  explicit Hdf5TreeFile(const std::filesystem::path& path);
  ~Hdf5TreeFile();  // removes the temporary file unless committed
  Hdf5TreeFile(const Hdf5TreeFile&) = delete;
  Hdf5TreeFile& operator=(const Hdf5TreeFile&) = delete;

  // Group at a '/'-separated path below the root (its parent must exist).
  void create_group(const std::string& path);
  // Dataset of dims[0] x dims[1] x ... elements (C order) at `path`; empty dims: a scalar.
  void write_dataset(const std::string& path, Hdf5Element type, const void* data, const std::vector<std::size_t>& dims);
  // Attributes of the group or dataset at `object` ("/" for the root).
  void write_attribute(const std::string& object, const std::string& name, double value);
  void write_attribute(const std::string& object, const std::string& name, std::int64_t value);
  void write_attribute(const std::string& object, const std::string& name, const std::string& value);
  // Closes the file and renames it to the final path.
  void commit();

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace lrchain::jobs

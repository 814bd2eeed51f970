// HDF5 files of groups, datasets and attributes through the HDF5 C API (hdf5_tree.hpp).
#include "lrchain/jobs/hdf5_tree.hpp"

#include <hdf5.h>

#include <stdexcept>
#include <system_error>

#include "lrchain/errors.hpp"
#include "lrchain/output_target.hpp"
#include "lrchain/jobs/output_files.hpp"

namespace lrchain::jobs {

namespace {

// An HDF5 identifier closed by `close` when it goes out of scope.
class Id {
 public:
  Id(hid_t id, herr_t (*close)(hid_t), const std::string& what) : id_(id), close_(close) {
    if (id_ < 0) throw std::runtime_error("HDF5: cannot " + what);
  }
  ~Id() { close_(id_); }
  Id(const Id&) = delete;
  Id& operator=(const Id&) = delete;
  operator hid_t() const { return id_; }

 private:
  hid_t id_;
  herr_t (*close_)(hid_t);
};

void check(herr_t status, const std::string& what) {
  if (status < 0) throw std::runtime_error("HDF5: cannot " + what);
}

// The file's type of an element (a new type id, closed by the caller): native numbers, complex as
// the compound {r, i} (h5py's convention).
hid_t element_type(Hdf5Element e) {
  switch (e) {
    case Hdf5Element::float64: return H5Tcopy(H5T_NATIVE_DOUBLE);
    case Hdf5Element::float32: return H5Tcopy(H5T_NATIVE_FLOAT);
    case Hdf5Element::int64: return H5Tcopy(H5T_NATIVE_INT64);
    case Hdf5Element::int32: return H5Tcopy(H5T_NATIVE_INT32);
    case Hdf5Element::int8: return H5Tcopy(H5T_NATIVE_INT8);
    case Hdf5Element::complex128: {
      const hid_t t = H5Tcreate(H5T_COMPOUND, 2 * sizeof(double));
      if (t >= 0 && (H5Tinsert(t, "r", 0, H5T_NATIVE_DOUBLE) < 0 || H5Tinsert(t, "i", sizeof(double), H5T_NATIVE_DOUBLE) < 0)) {
        H5Tclose(t);
        return -1;
      }
      return t;
    }
  }
  return -1;
}

}  // namespace

struct Hdf5TreeFile::State {
  std::filesystem::path path, temporary;
  hid_t file = -1;
  bool committed = false;

  // The group or dataset at `object` (H5Oopen), closed by the caller's Id.
  hid_t open(const std::string& object) const { return H5Oopen(file, object.c_str(), H5P_DEFAULT); }

  void write_attribute(const std::string& object, const std::string& name, hid_t type, const void* value) {
    const Id where(open(object), H5Oclose, "open '" + object + "'");
    const Id space(H5Screate(H5S_SCALAR), H5Sclose, "make a scalar space");
    const Id a(H5Acreate2(where, name.c_str(), type, space, H5P_DEFAULT, H5P_DEFAULT), H5Aclose,
               "create attribute " + name);
    check(H5Awrite(a, type, value), "write attribute " + name);
  }
};

Hdf5TreeFile::Hdf5TreeFile(const std::filesystem::path& path) : state_(std::make_unique<State>()) {
  std::error_code ec;
  const std::filesystem::path directory = path.has_parent_path() ? path.parent_path() : ".";
  if (!std::filesystem::is_directory(directory, ec))
    throw InputError(path.string() + ": the directory " + directory.string() + " does not exist");
  check_output_target(path);  // a directory, device, FIFO or socket is never replaced
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);  // failures are reported through exceptions
  state_->path = path;
  state_->temporary = temporary_name(path);
  state_->file = H5Fcreate(state_->temporary.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
  if (state_->file < 0) throw InputError(path.string() + ": cannot create the file (is its directory writable?)");
}

Hdf5TreeFile::~Hdf5TreeFile() {
  if (state_->file >= 0) H5Fclose(state_->file);
  if (!state_->committed) {
    std::error_code ec;
    std::filesystem::remove(state_->temporary, ec);
  }
}

void Hdf5TreeFile::create_group(const std::string& path) {
  const Id g(H5Gcreate2(state_->file, path.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose,
             "create group '" + path + "'");
}

void Hdf5TreeFile::write_dataset(const std::string& path, Hdf5Element type, const void* data,
                                 const std::vector<std::size_t>& dims) {
  const std::vector<hsize_t> extent(dims.begin(), dims.end());
  const Id space(dims.empty() ? H5Screate(H5S_SCALAR) : H5Screate_simple(int(extent.size()), extent.data(), nullptr),
                 H5Sclose, "make a data space");
  const Id t(element_type(type), H5Tclose, "make the type of dataset '" + path + "'");
  const Id d(H5Dcreate2(state_->file, path.c_str(), t, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Dclose,
             "create dataset '" + path + "'");
  check(H5Dwrite(d, t, H5S_ALL, H5S_ALL, H5P_DEFAULT, data), "write dataset '" + path + "'");
}

void Hdf5TreeFile::write_attribute(const std::string& object, const std::string& name, double value) {
  state_->write_attribute(object, name, H5T_NATIVE_DOUBLE, &value);
}

void Hdf5TreeFile::write_attribute(const std::string& object, const std::string& name, std::int64_t value) {
  state_->write_attribute(object, name, H5T_NATIVE_INT64, &value);
}

void Hdf5TreeFile::write_attribute(const std::string& object, const std::string& name, const std::string& value) {
  const Id t(H5Tcopy(H5T_C_S1), H5Tclose, "make a string type");
  check(H5Tset_size(t, H5T_VARIABLE), "size a string type");
  check(H5Tset_cset(t, H5T_CSET_UTF8), "set a string type's character set");
  const char* text = value.c_str();
  state_->write_attribute(object, name, t, &text);
}

void Hdf5TreeFile::commit() {
  check(H5Fflush(state_->file, H5F_SCOPE_GLOBAL), "flush '" + state_->temporary.string() + "'");
  check(H5Fclose(state_->file), "close '" + state_->temporary.string() + "'");
  state_->file = -1;
  check_output_target(state_->path);  // (it may have been made a FIFO since the constructor)
  std::error_code ec;
  std::filesystem::rename(state_->temporary, state_->path, ec);
  if (ec) throw std::runtime_error("cannot rename " + state_->temporary.string() + " to " + state_->path.string() + ": " + ec.message());
  state_->committed = true;
}

}  // namespace lrchain::jobs

// lrchain._hdf5: lrchain's results to HDF5, a nested dict {name: dict (group) | numpy array (dataset) |
// number or str (attribute of the enclosing group)} written by sim::Hdf5TreeFile (temporary name +
// rename). A module of its own, imported by result.to_hdf5(): `import lrchain` does not load libhdf5.
#include <complex>
#include <pybind11/numpy.h>

#include <pybind11/pybind11.h>
#include "lrchain/errors.hpp"
#include "lrchain/sim/hdf5_tree.hpp"
#include "lrchain/version.hpp"

namespace py = pybind11;

namespace lrchain::python {

namespace {

using sim::Hdf5Element;

// The element type of a numpy array; TypeError naming the dataset for other dtypes.
Hdf5Element element_of(const py::array& a, const std::string& path) {
  const py::dtype t = a.dtype();
  if (t.is(py::dtype::of<double>())) return Hdf5Element::float64;
  if (t.is(py::dtype::of<float>())) return Hdf5Element::float32;
  if (t.is(py::dtype::of<std::int64_t>())) return Hdf5Element::int64;
  if (t.is(py::dtype::of<std::int32_t>())) return Hdf5Element::int32;
  if (t.is(py::dtype::of<std::int8_t>())) return Hdf5Element::int8;
  if (t.is(py::dtype::of<std::complex<double>>())) return Hdf5Element::complex128;
  throw py::type_error("to_hdf5: dataset " + path + " has dtype " + std::string(py::str(py::handle(t))) +
                       " (float64, float32, int64, int32, int8 or complex128 are written)");
}

// Writes the items of `tree` below the group `group` ("" for the root).
void write_tree(sim::Hdf5TreeFile& file, const std::string& group, const py::dict& tree) {
  const std::string object = group.empty() ? "/" : group;
  for (auto [key, value] : tree) {
    const std::string name = py::str(key);
    const std::string path = group + "/" + name;
    if (value.is_none()) continue;
    if (py::isinstance<py::dict>(value)) {
      file.create_group(path);
      write_tree(file, path, value.cast<py::dict>());
    } else if (py::isinstance<py::array>(value)) {
      const auto a = py::array::ensure(value, py::array::c_style);
      const std::vector<std::size_t> dims(a.shape(), a.shape() + a.ndim());
      file.write_dataset(path, element_of(a, path), a.data(), dims);
    } else if (py::isinstance<py::bool_>(value) || py::isinstance<py::int_>(value)) {
      file.write_attribute(object, name, value.cast<std::int64_t>());
    } else if (py::isinstance<py::float_>(value)) {
      file.write_attribute(object, name, value.cast<double>());
    } else if (py::isinstance<py::str>(value)) {
      file.write_attribute(object, name, value.cast<std::string>());
    } else {
      throw py::type_error("to_hdf5: " + path + " is a " + std::string(py::str(value.get_type().attr("__name__"))) +
                           " (dict, numpy array, number or str are written)");
    }
  }
}

// Validates the destination, writes the tree to a temporary file, renames it into place.
void write_hdf5(const std::string& path, const py::dict& tree) {
  sim::Hdf5TreeFile file(path);
  write_tree(file, "", tree);
  file.commit();
}

}  // namespace

}  // namespace lrchain::python

PYBIND11_MODULE(_hdf5, m) {
  using namespace lrchain::python;
  m.doc() = "HDF5 writer of lrchain's results (the HDF5 C library).";
  m.def("write_hdf5", &write_hdf5, py::arg("path"), py::arg("tree"),
        "Writes {name: dict | array | number | str} as HDF5 groups, datasets and attributes.");
  m.attr("version") = LRCHAIN_VERSION_STRING;
}

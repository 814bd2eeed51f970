// lrchain._hdf5's writers of coefficients, regime results and bright breathers: each rebuilds the job
// layer's record (jobs/coeffs_hdf5.hpp, jobs/regime_hdf5.hpp, jobs/bright_breather_hdf5.hpp) from a
// Python result's fields and writes the file the command writes.
#include <pybind11/stl.h>

#include "arrays.hpp"
#include "lrchain/errors.hpp"
#include "lrchain/jobs/bright_breather_hdf5.hpp"
#include "lrchain/jobs/wave_hdf5.hpp"
#include "lrchain/jobs/coeffs_hdf5.hpp"
#include "lrchain/jobs/regime_hdf5.hpp"

namespace py = pybind11;

namespace lrchain::python {

namespace {

using nlohmann::json;

// theta's shape as the writers take it (empty for a number).
std::vector<std::size_t> shape_of(const py::handle& a) {
  const auto c = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(a);
  if (!c) throw py::type_error("to_hdf5: expected a numeric array");
  return std::vector<std::size_t>(c.shape(), c.shape() + c.ndim());
}

// Coefficients.to_hdf5: `columns` {name: array} in coefficient_column_names(), `model` as JSON text.
void write_coefficients(const std::string& path, const std::string& model, const std::string& branch,
                        const py::handle& theta, const py::dict& columns, const py::handle& regime_code) {
  jobs::CoefficientsRecord r;
  r.model = json::parse(model);
  r.branch = branch;
  r.shape = shape_of(theta);
  r.theta = vector_of<double>(theta);
  for (const std::string& name : jobs::coefficient_column_names())
    r.columns.push_back({name, vector_of<double>(columns[py::str(name)])});
  r.regime_code = vector_of<std::int8_t>(regime_code);
  jobs::write_coefficients_hdf5(path, r);
}

void write_intervals(const std::string& path, const std::string& model, const std::string& branch, const py::handle& lo,
                     const py::handle& hi, const std::vector<std::string>& lo_cause,
                     const std::vector<std::string>& hi_cause, const py::handle& roots,
                     const std::vector<std::string>& root_cause) {
  jobs::IntervalsRecord r{json::parse(model), branch, vector_of<double>(lo), vector_of<double>(hi),
                          vector_of<double>(roots), lo_cause, hi_cause, root_cause};
  jobs::write_intervals_hdf5(path, r);
}

// [(cause, points (k, 2))] as the records.
std::vector<jobs::CurveRecord> curves_of(const py::list& curves) {
  std::vector<jobs::CurveRecord> out;
  for (const auto& item : curves) {
    const auto c = item.cast<py::tuple>();
    out.push_back({c[0].cast<std::string>(), vector_of<double>(c[1])});
  }
  return out;
}

void write_regime_map(const std::string& path, const std::string& model, const std::string& branch,
                      const std::string& plane, const std::string& x_name, const std::string& y_name,
                      const py::handle& x, const py::handle& y, const py::handle& values, const py::list& curves) {
  jobs::RegimeMapRecord r{json::parse(model), branch, plane, x_name, y_name, vector_of<double>(x),
                          vector_of<double>(y), vector_of<std::int8_t>(values), curves_of(curves)};
  if (r.values.size() != r.x.size() * r.y.size()) throw py::value_error("to_hdf5: values must be (len(y), len(x))");
  jobs::write_regime_map_hdf5(path, r);
}

void write_boundary_curve(const std::string& path, const std::string& model, const std::string& branch,
                          const std::string& axis, const std::string& y_name, const std::string& cause,
                          const py::handle& points) {
  jobs::write_boundary_curve_hdf5(path, {json::parse(model), branch, axis, y_name, {cause, vector_of<double>(points)}});
}

// BrightBreather.to_hdf5 / BrightBranch.to_hdf5 / BrightEvolution.to_hdf5: the summary as JSON text, Z(0),
// the seed, (a branch) every point's Z(0) and (an evolution) t, deviation and energy (None: no potential).
void write_bright_breather(const std::string& path, const std::string& summary, const std::vector<std::string>& variables,
                           const py::handle& z, const py::handle& seed, const py::object& branch_z,
                           const py::object& evolution_t, const py::object& evolution_deviation,
                           const py::object& evolution_energy) {
  jobs::bright_breather::BrightBreatherRecord r;
  r.summary = json::parse(summary);
  r.variables = variables;
  r.z = vector_of<double>(z);
  r.seed = vector_of<double>(seed);
  r.sites = variables.empty() ? 0 : Index(r.z.size() / variables.size());
  r.branch = !branch_z.is_none();
  if (r.branch) r.branch_z = vector_of<double>(branch_z);
  r.evolution = !evolution_t.is_none();
  if (r.evolution) {
    const std::vector<double> t = vector_of<double>(evolution_t), deviation = vector_of<double>(evolution_deviation);
    const std::vector<double> energy = evolution_energy.is_none() ? std::vector<double>{} : vector_of<double>(evolution_energy);
    if (deviation.size() != t.size() || (!energy.empty() && energy.size() != t.size()))
      throw InvalidParameter("evolution", "t, deviation and energy must have the same length");
    r.periods.names = energy.empty() ? std::vector<std::string>{"t", "deviation"} : std::vector<std::string>{"t", "deviation", "energy"};
    for (std::size_t m = 0; m < t.size(); ++m) {
      r.periods.data.insert(r.periods.data.end(), {t[m], deviation[m]});
      if (!energy.empty()) r.periods.data.push_back(energy[m]);
    }
  }
  jobs::bright_breather::write_bright_breather_hdf5(path, r);
}

// TravellingWave.to_hdf5 / WaveBranch.to_hdf5: everything is in the wave job's summary.
void write_wave(const std::string& path, const std::string& summary) {
  jobs::wave::write_wave_hdf5(path, json::parse(summary));
}

}  // namespace

void register_regime_and_bright_writers(py::module_& m) {
  m.def("write_coefficients", &write_coefficients, py::arg("path"), py::arg("model"), py::arg("branch"),
        py::arg("theta"), py::arg("columns"), py::arg("regime_code"),
        "Writes NLS coefficients with the job layer's writer (the file of lrchain coeffs --out).");
  m.def("write_intervals", &write_intervals, py::arg("path"), py::arg("model"), py::arg("branch"), py::arg("lo"),
        py::arg("hi"), py::arg("lo_cause"), py::arg("hi_cause"), py::arg("roots"), py::arg("root_cause"),
        "Writes focusing intervals with the job layer's writer (lrchain regime intervals --out).");
  m.def("write_regime_map", &write_regime_map, py::arg("path"), py::arg("model"), py::arg("branch"), py::arg("plane"),
        py::arg("x_name"), py::arg("y_name"), py::arg("x"), py::arg("y"), py::arg("values"), py::arg("curves"),
        "Writes a regime map with the job layer's writer (lrchain regime map --format hdf5).");
  m.def("write_boundary_curve", &write_boundary_curve, py::arg("path"), py::arg("model"), py::arg("branch"),
        py::arg("axis"), py::arg("y_name"), py::arg("cause"), py::arg("points"),
        "Writes one boundary curve with the job layer's writer.");
  m.def("write_wave", &write_wave, py::arg("path"), py::arg("summary"),
        "Writes a travelling wave or wave branch with the job layer's writer (lrchain wave ... --format hdf5).");
  m.def("write_bright_breather", &write_bright_breather, py::arg("path"), py::arg("summary"), py::arg("variables"),
        py::arg("z"), py::arg("seed"), py::arg("branch_z"), py::arg("evolution_t") = py::none(),
        py::arg("evolution_deviation") = py::none(), py::arg("evolution_energy") = py::none(),
        "Writes a bright breather, branch or evolution with the job layer's writer (lrchain bright ... --format hdf5).");
}

}  // namespace lrchain::python

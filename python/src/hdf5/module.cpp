// lrchain._hdf5: lrchain's results to HDF5 through the C++ writers of the CLI's `--format hdf5` files
// (sim/result_hdf5.hpp, sim/dark/dark_hdf5.hpp, jobs/simulate/model_run_hdf5.hpp,
// jobs/model_dark_hdf5.hpp, jobs/dark_evolution_hdf5.hpp; coefficients, regime and bright breathers:
// regime_bright_writers.cpp): each function rebuilds the writer's
// record from a Python result's fields. A module of its own, imported by result.to_hdf5(): `import
// lrchain` does not load libhdf5.
#include <complex>
#include <pybind11/numpy.h>

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include "arrays.hpp"
#include "lrchain/errors.hpp"
#include "lrchain/jobs/dark_evolution_hdf5.hpp"
#include "lrchain/jobs/model_dark_hdf5.hpp"
#include "lrchain/jobs/simulate/model_run_hdf5.hpp"
#include "lrchain/output_target.hpp"
#include "lrchain/jobs/dark_hdf5.hpp"
#include "lrchain/jobs/result_hdf5.hpp"
#include "lrchain/version.hpp"

namespace py = pybind11;

namespace lrchain::python {

namespace {



// A series {column: array} of equal-length arrays as row-major columns.
sim::TimeSeries series_of(const py::dict& series) {
  sim::TimeSeries s;
  std::vector<std::vector<double>> columns;
  for (auto [name, values] : series) {
    s.names.push_back(py::str(name));
    columns.push_back(vector_of<double>(values));
  }
  const std::size_t rows = columns.empty() ? 0 : columns[0].size();
  for (std::size_t r = 0; r < rows; ++r)
    for (const auto& c : columns) s.data.push_back(c.at(r));
  return s;
}

// The run's record from a Python result's arrays: `series` {record column: array}, `field`
// (quantity, n, t, values) of the energy density or None (model-file runs record none),
// `snapshots` [(t, tag, {column: array})]; the same numbers as the C++ record the result was made
// from (float32 space-time values stay float32).
sim::RunRecord record_of(const py::dict& series, const py::object& energy_density, const py::list& snapshots) {
  sim::RunRecord record;
  record.series = series_of(series);
  if (!energy_density.is_none()) {
    const auto field = energy_density.cast<py::tuple>();
    sim::SpaceTime f;
    f.quantity = field[0].cast<std::string>();
    const std::vector<double> n = vector_of<double>(field[1]);
    f.first_label = n.empty() ? 0 : long(n[0]);
    f.sites = n.size();
    f.times = vector_of<double>(field[2]);
    f.values = vector_of<float>(field[3]);
    record.fields.push_back(std::move(f));
  }
  for (const auto& item : snapshots) {
    const auto s = item.cast<py::tuple>();
    sim::Snapshot snap;
    snap.t = s[0].cast<double>();
    snap.tag = s[1].cast<std::string>();
    std::vector<std::vector<double>> cols;
    for (auto [name, values] : s[2].cast<py::dict>()) {
      snap.names.push_back(py::str(name));
      cols.push_back(vector_of<double>(values));
    }
    const std::size_t length = cols.empty() ? 0 : cols[0].size();
    for (std::size_t r = 0; r < length; ++r)
      for (const auto& c : cols) snap.data.push_back(c.at(r));
    record.snapshots.push_back(std::move(snap));
  }
  return record;
}

// A simulation result through the sim library's writer (the file `lrchain simulate --format hdf5`
// writes); `extra` [(name, quantity, n, t, values)] are the fields recorded at every sample.
void write_simulation(const std::string& path, const std::string& kind, const py::dict& series, const py::object& field,
                      const py::list& snapshots, const std::string& summary_json, const py::list& extra) {
  const jobs::SimulationKind k = jobs::simulation_kind(kind);
  const sim::RunRecord record = record_of(series, field, snapshots);
  std::vector<jobs::SampledField> fields;
  for (const auto& item : extra) {
    const auto e = item.cast<py::tuple>();
    fields.push_back({e[0].cast<std::string>(), e[1].cast<std::string>(), vector_of<double>(e[2]),
                      vector_of<double>(e[3]), vector_of<double>(e[4])});
  }
  jobs::write_simulation_hdf5(path, k, record, nlohmann::json::parse(summary_json), fields);
}

// A model file's bright run through the job layer's writer (the file `lrchain simulate bright --model
// ... --format hdf5` writes): series {t, E_0, ..., energy, X}, snapshots as for write_simulation.
void write_model_bright(const std::string& path, const py::dict& series, const py::list& snapshots,
                        const std::string& summary_json) {
  jobs::write_model_bright_hdf5(path, record_of(series, py::none(), snapshots), nlohmann::json::parse(summary_json));
}

// A ring run through the job layer's writer (`lrchain simulate ring ... --format hdf5`): the packet's
// series {t, packet_centre} and the per-amplitude table {amplitude, measured_frequency, ...}.
void write_ring(const std::string& path, const py::dict& series, const py::dict& amplitudes,
                const std::string& summary_json) {
  jobs::write_ring_hdf5(path, record_of(series, py::none(), py::list()), series_of(amplitudes),
                        nlohmann::json::parse(summary_json));
}

Params params_of(const py::tuple& p) {
  return Params{p[0].cast<double>(), p[1].cast<double>(), p[2].cast<double>(), p[3].cast<double>()};
}

// The measures; K_y, C_y None (a model without a second strain-form variable, not written) read as 0.
sim::dark::DarkMeasures measures_of(const py::dict& m) {
  const auto optional = [](const py::handle& v) { return v.is_none() ? 0.0 : v.cast<double>(); };
  sim::dark::DarkMeasures r;
  r.norm_squared = m["norm_squared"].cast<double>();
  r.K_x = m["K_x"].cast<double>();
  r.K_y = optional(m["K_y"]);
  r.C_x = m["C_x"].cast<double>();
  r.C_y = optional(m["C_y"]);
  r.E_b = m["E_b"].cast<double>();
  r.max_strain = m["max_strain"].cast<double>();
  return r;
}

jobs::dark::FloquetRecord floquet_of(const py::dict& f) {
  jobs::dark::FloquetRecord r;
  r.multipliers = vector_of<std::complex<double>>(f["multipliers"]);
  r.kind = f["kind"].cast<std::string>();
  r.max_modulus = f["max_modulus"].cast<double>();
  r.max_real = f["max_real"].cast<double>();
  r.max_period_doubling = f["max_period_doubling"].cast<double>();
  r.max_oscillatory = f["max_oscillatory"].cast<double>();
  r.near_one = f["near_one"].cast<Index>();
  r.pairing_defect = f["pairing_defect"].cast<double>();
  r.conjugation_defect = f["conjugation_defect"].cast<double>();
  r.log_det = f["log_det"].cast<double>();
  return r;
}

// A dark breather through the sim library's writer (the file `lrchain dark solve|floquet --format hdf5`
// writes): `d` holds the DarkSolution's fields (floquet: a dict or None), `params` (alpha, delta0, kappa, rho).
void write_dark_solution(const std::string& path, const py::tuple& params, const py::dict& d) {
  jobs::dark::DarkSolutionRecord r;
  r.params = params_of(params);
  r.omega_b = d["omega_b"].cast<double>();
  r.omega_edge = d["omega_edge"].cast<double>();
  r.x = vector_of<double>(d["x"]);
  r.y = vector_of<double>(d["y"]);
  r.x_seed = vector_of<double>(d["x_seed"]);
  r.y_seed = vector_of<double>(d["y_seed"]);
  r.newton_residuals = vector_of<double>(d["newton_residuals"]);
  r.measures = measures_of(d["measures"].cast<py::dict>());
  if (!d["floquet"].is_none()) r.floquet = floquet_of(d["floquet"].cast<py::dict>());
  jobs::dark::write_dark_solution_hdf5(path, r);
}

// A branch through the sim library's writer (`lrchain dark continue --format hdf5`): `d` holds the
// Branch's fields (measures: list of dicts; floquet: list of dicts, or None when not computed).
// The per-point series of a branch (omega_b, ..., measures, floquet, turning_points, stop_reason).
jobs::dark::DarkBranchRecord branch_points_of(const py::dict& d) {
  jobs::dark::DarkBranchRecord r;
  r.omega_b = vector_of<double>(d["omega_b"]);
  r.tangent_omega = vector_of<double>(d["tangent_omega"]);
  r.residual = vector_of<double>(d["residual"]);
  r.iterations = vector_of<Index>(d["iterations"]);
  for (const auto& m : d["measures"].cast<py::list>()) r.measures.push_back(measures_of(m.cast<py::dict>()));
  if (!d["floquet"].is_none())
    for (const auto& f : d["floquet"].cast<py::list>()) r.floquet.push_back(floquet_of(f.cast<py::dict>()));
  r.turning_points = d["turning_points"].cast<std::vector<double>>();
  r.stop_reason = d["stop_reason"].cast<std::string>();
  return r;
}

void write_dark_branch(const std::string& path, const py::tuple& params, const py::dict& d) {
  jobs::dark::DarkBranchRecord r = branch_points_of(d);
  r.params = params_of(params);
  const auto x = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(d["x"]);
  r.sites = x.ndim() == 2 ? Index(x.shape(1)) : 0;
  r.x = vector_of<double>(d["x"]);
  r.y = vector_of<double>(d["y"]);
  jobs::dark::write_dark_branch_hdf5(path, r);
}

// The edge of a model-file dark result from its fields (model: a dict; lambda_ None without mean flow).
jobs::dark::ModelDarkEdgeRecord edge_of(const py::dict& d) {
  jobs::dark::ModelDarkEdgeRecord e;
  e.model = nlohmann::json::parse(py::module_::import("json").attr("dumps")(d["model"]).cast<std::string>());
  e.branch = d["branch"].cast<std::string>();
  e.theta = d["theta"].cast<double>();
  e.omega_edge = d["omega_edge"].cast<double>();
  e.curvature = d["curvature"].cast<double>();
  e.h_tilde = d["h_tilde"].cast<double>();
  if (!d["lambda_"].is_none()) e.lambda = d["lambda_"].cast<double>();
  e.lattice_form = d["lattice_form"].cast<std::string>();
  e.variables = d["variables"].cast<std::vector<std::string>>();
  e.one_sided_contacts = d["one_sided_contacts"].cast<std::vector<std::string>>();
  e.sites = Index(py::len(d["n"]));
  return e;
}

// A model file's dark breather through the job layer's writer (the file `lrchain dark solve|floquet
// --model ... --format hdf5` writes): `d` holds the ModelDarkSolution's fields.
void write_model_dark_solution(const std::string& path, const py::dict& d) {
  jobs::dark::ModelDarkSolutionRecord r;
  r.edge = edge_of(d);
  r.omega_b = d["omega_b"].cast<double>();
  r.z = vector_of<double>(d["z"]);
  r.seed = vector_of<double>(d["seed"]);
  r.newton_residuals = vector_of<double>(d["newton_residuals"]);
  r.measures = measures_of(d["measures"].cast<py::dict>());
  if (!d["floquet"].is_none()) r.floquet = floquet_of(d["floquet"].cast<py::dict>());
  if (!d["contact_changes_per_period"].is_none()) r.contact_changes_per_period = d["contact_changes_per_period"].cast<Index>();
  jobs::dark::write_model_dark_solution_hdf5(path, r);
}

// A model file's branch through the job layer's writer (`lrchain dark continue --model ... --format
// hdf5`): `d` holds the ModelBranch's fields (floquet: list of dicts, or None when not computed).
void write_model_dark_branch(const std::string& path, const py::dict& d) {
  jobs::dark::ModelDarkBranchRecord r;
  r.edge = edge_of(d);
  r.points = branch_points_of(d);
  r.z = vector_of<double>(d["z"]);
  for (const auto& count : d["contact_changes_per_period"].cast<py::list>())
    if (!count.is_none()) r.contact_changes_per_period.push_back(count.cast<Index>());
  if (r.contact_changes_per_period.size() != r.points.omega_b.size()) r.contact_changes_per_period.clear();
  if (d.contains("parameter") && !d["parameter"].is_none()) r.parameter = d["parameter"].cast<std::string>();
  if (d.contains("parameter_values") && !d["parameter_values"].is_none())
    r.parameter_values = vector_of<double>(d["parameter_values"]);
  else
    r.parameter_values = r.points.omega_b;
  jobs::dark::write_model_dark_branch_hdf5(path, r);
}

// The record of an Evolution or ModelEvolution from its fields: the per-period series and the
// stroboscopic profiles `profiles` ((M+1) x fields x sites).
jobs::dark::DarkEvolutionRecord evolution_of(const py::dict& d, const py::handle& profiles, Index fields, Index sites) {
  jobs::dark::DarkEvolutionRecord e;
  e.period = d["period"].cast<double>();
  e.max_strain = d["max_strain"].cast<double>();
  py::dict series;
  for (const char* name : {"t", "E_b", "C_x", "K_x", "position", "depth"}) series[name] = d[name];
  e.periods = series_of(series);
  e.fields = fields;
  e.sites = sites;
  e.profiles = vector_of<double>(profiles);
  return e;
}

// The resonant chain's evolution through the job layer's writer (`lrchain dark evolve --format hdf5`):
// the profiles x, y (M+1, sites) interleaved per row as the writer's (M+1) x 2 x sites.
void write_dark_evolution(const std::string& path, const py::tuple& params, const py::dict& d) {
  const auto x = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(d["x"]);
  const auto y = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(d["y"]);
  const py::object stacked = py::module_::import("numpy").attr("stack")(py::make_tuple(x, y), 1);
  const Index sites = x.ndim() == 2 ? Index(x.shape(1)) : 0;
  jobs::dark::write_dark_evolution_hdf5(path, params_of(params), evolution_of(d, stacked, 2, sites));
}

// A model file's evolution through the job layer's writer (`lrchain dark evolve --model ... --format hdf5`).
void write_model_dark_evolution(const std::string& path, const py::dict& d) {
  const jobs::dark::ModelDarkEdgeRecord edge = edge_of(d);
  jobs::dark::write_model_dark_evolution_hdf5(
      path, edge, evolution_of(d, d["z"], Index(edge.variables.size()), edge.sites));
}

}  // namespace

}  // namespace lrchain::python

PYBIND11_MODULE(_hdf5, m) {
  using namespace lrchain::python;
  m.doc() = "HDF5 writer of lrchain's results (the HDF5 C library).";
  m.def("write_simulation", &write_simulation, py::arg("path"), py::arg("kind"), py::arg("series"), py::arg("field"),
        py::arg("snapshots"), py::arg("summary_json"), py::arg("extra"),
        "Writes a bright/drive/modulated run with the sim library's writer (the CLI's --format hdf5 file).");
  m.def("write_model_bright", &write_model_bright, py::arg("path"), py::arg("series"), py::arg("snapshots"),
        py::arg("summary_json"),
        "Writes a model file's bright run with the job layer's writer (the CLI's simulate bright --model --format hdf5 file).");
  m.def("write_ring", &write_ring, py::arg("path"), py::arg("series"), py::arg("amplitudes"), py::arg("summary_json"),
        "Writes a ring run with the job layer's writer (the CLI's simulate ring --format hdf5 file).");
  m.def("write_model_dark_solution", &write_model_dark_solution, py::arg("path"), py::arg("solution"),
        "Writes a model file's dark breather with the job layer's writer (dark solve|floquet --model --format hdf5).");
  m.def("write_model_dark_branch", &write_model_dark_branch, py::arg("path"), py::arg("branch"),
        "Writes a model file's dark-breather branch with the job layer's writer (dark continue --model --format hdf5).");
  m.def("write_dark_evolution", &write_dark_evolution, py::arg("path"), py::arg("params"), py::arg("evolution"),
        "Writes a dark breather's evolution with the job layer's writer (dark evolve --format hdf5).");
  m.def("write_model_dark_evolution", &write_model_dark_evolution, py::arg("path"), py::arg("evolution"),
        "Writes a model file's dark-breather evolution with the job layer's writer (dark evolve --model --format hdf5).");
  m.def("write_dark_solution", &write_dark_solution, py::arg("path"), py::arg("params"), py::arg("solution"),
        "Writes a dark breather with the sim library's writer (the CLI's dark solve|floquet --format hdf5 file).");
  m.def("write_dark_branch", &write_dark_branch, py::arg("path"), py::arg("params"), py::arg("branch"),
        "Writes a dark-breather branch with the sim library's writer (the CLI's dark continue --format hdf5 file).");
  m.def(
      "output_target_problem",
      [](const std::string& path) -> std::string {
        try {
          lrchain::check_output_target(path);
          return {};
        } catch (const lrchain::InputError& e) {
          return e.what();
        }
      },
      py::arg("path"), "Why `path` may not be written (lrchain::check_output_target, every writer's check), or ''.");
  register_regime_and_bright_writers(m);
  m.attr("version") = LRCHAIN_VERSION_STRING;
}

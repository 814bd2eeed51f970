// lrchain.regime (Sec. 3.3): the regime jobs (lrchain/jobs/regime_job.hpp) of the resonant chain
// (a Params) or of a loaded model (lrchain.Model): focusing intervals, pixel maps, boundary curves
// and thresholds, as numpy arrays; run without the GIL.
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "loaded_model.hpp"
#include "lrchain/config/option_caps.hpp"
#include "lrchain/dispersion.hpp"
#include "lrchain/jobs/regime_job.hpp"
#include "lrchain/model_json.hpp"
#include "lrchain/regime/frequency_band.hpp"

namespace py = pybind11;

namespace lrchain::python {

namespace {
using namespace lrchain::regime;
using Range = jobs::Range;

// A Params (the resonant chain, its specialised evaluators) or an lrchain.Model.
jobs::RegimeLattice lattice_of(const py::handle& lattice) {
  if (py::isinstance<LoadedModel>(lattice))
    return {Params{}, std::make_shared<const Model>(lattice.cast<const LoadedModel&>().model)};
  return {lattice.cast<Params>(), nullptr};
}

// jobs::run(config) with the GIL released (the job holds no Python object).
template <class Config>
auto run_without_gil(const Config& config) {
  py::gil_scoped_release release;
  return jobs::run(config);
}

py::array_t<double> axis_values(const GridAxis& a) {
  py::array_t<double> v(a.n);
  for (Index i = 0; i < a.n; ++i) v.mutable_at(i) = a.at(i);
  return v;
}

// Roots of the four smooth functions along (0, pi] and the focusing intervals between them.
py::dict structure(const py::handle& lattice, const std::string& branch, int samples, double tolerance) {
  jobs::RegimeIntervalsConfig c;
  c.lattice = lattice_of(lattice);
  c.branch = branch;
  c.samples = samples;
  c.tolerance = tolerance;
  const auto r = run_without_gil(c);
  const auto& s = r.structure;
  py::array_t<double> lo(s.intervals.size()), hi(s.intervals.size()), roots(s.roots.size());
  py::list lo_cause, hi_cause, root_cause;
  for (std::size_t k = 0; k < s.intervals.size(); ++k) {
    lo.mutable_at(k) = s.intervals[k].lo;
    hi.mutable_at(k) = s.intervals[k].hi;
    lo_cause.append(std::string(to_string(s.intervals[k].lo_cause)));
    hi_cause.append(std::string(to_string(s.intervals[k].hi_cause)));
  }
  for (std::size_t k = 0; k < s.roots.size(); ++k) {
    roots.mutable_at(k) = s.roots[k].theta;
    root_cause.append(std::string(to_string(s.roots[k].cause)));
  }
  py::dict d;
  d["branch"] = r.branch;
  d["model"] = r.model.dump();
  d["lo"] = lo;
  d["hi"] = hi;
  d["lo_cause"] = lo_cause;
  d["hi_cause"] = hi_cause;
  d["roots"] = roots;
  d["root_cause"] = root_cause;
  return d;
}

// One branch's pixel map of `plane` ("theta-rho", "delta0-omega", "theta-parameter") as a (y.n, x.n)
// int8 array with the axis values, ready for pcolormesh(x, y, values). x/y: lo hi or None (the
// job's default).
py::dict map(const py::handle& lattice, const std::string& plane, const std::string& branch, const std::string& axis,
             std::optional<Range> x, int nx, std::optional<Range> y, int ny, bool x_log) {
  jobs::RegimeMapConfig c;
  c.lattice = lattice_of(lattice);
  c.plane = plane;
  c.branch = branch;
  c.axis = axis;
  c.nx = nx;
  c.ny = ny;
  c.curves = c.inset = c.bands = c.figures = false;
  if (plane == "delta0-omega") {
    c.delta0_range = x;
    c.omega_range = y;
    c.delta0_log = x_log;
  } else {
    (c.lattice.model ? c.axis_range : c.rho_range) = x;
    c.theta_range = y;
    c.rho_log = x_log;
  }
  const auto r = run_without_gil(c);
  const jobs::RegimeMapPanel& panel = r.panels.at(0);
  py::array_t<std::int8_t> values({panel.y.n, panel.x.n});
  std::copy(panel.values.begin(), panel.values.end(), values.mutable_data());
  py::dict d;
  d["branch"] = panel.branch;
  d["axis"] = r.axis;
  d["plane"] = r.plane;
  d["model"] = r.model.dump();
  d["x"] = axis_values(panel.x);
  d["y"] = axis_values(panel.y);
  d["values"] = values;
  return d;
}

// [(cause, points (k, 2): columns parameter, theta (or omega if omega_plane))] of every traced curve.
py::list curves(const py::handle& lattice, const std::string& branch, const std::string& axis,
                std::optional<Range> range, bool omega_plane) {
  jobs::RegimeCurvesConfig c;
  c.lattice = lattice_of(lattice);
  c.branch = branch;
  c.axis = axis;
  c.omega_plane = omega_plane;
  c.range = range;
  const auto traced = run_without_gil(c);
  py::list out;
  for (const BoundaryCurve& curve : traced) {
    py::array_t<double> pts({static_cast<py::ssize_t>(curve.points.size()), py::ssize_t(2)});
    auto w = pts.mutable_unchecked<2>();
    for (std::size_t k = 0; k < curve.points.size(); ++k) {
      w(k, 0) = curve.points[k].x;
      w(k, 1) = curve.points[k].y;
    }
    out.append(py::make_tuple(std::string(to_string(curve.cause)), pts));
  }
  return out;
}

// The JSON text of `lrchain regime thresholds` (without provenance): the paper's scenarios, or the
// events along one parameter of a model.
std::string thresholds(const py::object& model, int scan, const std::string& branch, const std::string& axis,
                       std::optional<Range> axis_range) {
  jobs::RegimeThresholdsConfig c;
  if (!model.is_none()) c.model = model.cast<const LoadedModel&>().model;
  c.scan = scan;
  c.branch = branch;
  c.axis = axis;
  c.axis_range = axis_range;
  const auto r = run_without_gil(c);
  return jobs::to_json(r).dump();
}

// The defaults of a map's x and y ranges for one branch of the resonant chain (the CLI's).
py::dict map_defaults(const Params& p, const std::string& branch) {
  validate(p);
  const Branch b = parse_branch(branch);
  py::dict d;
  d["rho"] = jobs::default_rho_range(b);
  d["delta0"] = jobs::default_delta0_range;
  d["omega"] = jobs::default_omega_range(p, b, jobs::default_delta0_range);
  return d;
}

// The jobs' defaults and ranges, for the docstrings and the test that Python's equal them.
py::dict job_defaults() {
  const jobs::RegimeIntervalsConfig intervals;
  const jobs::RegimeMapConfig map;
  const jobs::RegimeCurvesConfig curve;
  py::dict d;
  d["samples"] = intervals.samples;
  d["samples_range"] = py::make_tuple(config::intervals_samples.least, config::intervals_samples.most);
  d["tolerance"] = intervals.tolerance;
  d["nx"] = map.nx;
  d["ny"] = map.ny;
  d["nx_range"] = py::make_tuple(config::map_pixels_x.least, config::map_pixels_x.most);
  d["ny_range"] = py::make_tuple(config::map_pixels_y.least, config::map_pixels_y.most);
  d["rho_range_optical"] = jobs::default_rho_range(Branch::optical);
  d["rho_range_acoustic"] = jobs::default_rho_range(Branch::acoustic);
  d["delta0_range"] = jobs::default_delta0_range;
  d["curves_branch"] = curve.branch;
  d["thresholds_scan"] = jobs::RegimeThresholdsConfig{}.scan;
  return d;
}

// The model object of every result's provenance (lrchain/model_json.hpp) of a Params (the resonant
// chain) or an lrchain.Model, as JSON text.
// The parameter boundary_curves uses when none is named (jobs::default_axis).
std::string lattice_default_axis(const py::handle& lattice) { return jobs::default_axis(lattice_of(lattice)); }

std::string lattice_model_json(const py::handle& lattice) {
  const jobs::RegimeLattice l = lattice_of(lattice);
  if (l.model) return model_json(*l.model).dump();
  validate(l.params);
  return model_json(resonant_chain_model(l.params)).dump();
}

py::tuple band(const Params& p, const std::string& branch) {
  validate(p);
  const FrequencyBand f = frequency_band(p, parse_branch(branch));
  return py::make_tuple(f.lo, f.hi);
}

}  // namespace

void register_regime(py::module_& m) {
  m.def("regime_structure", &structure, py::arg("lattice"), py::arg("branch"), py::arg("samples"),
        py::arg("tolerance"));
  m.def("regime_map", &map, py::arg("lattice"), py::arg("plane"), py::arg("branch"), py::arg("axis"), py::arg("x"),
        py::arg("nx"), py::arg("y"), py::arg("ny"), py::arg("x_log"));
  m.def("boundary_curves", &curves, py::arg("lattice"), py::arg("branch"), py::arg("axis"), py::arg("range"),
        py::arg("omega_plane"));
  m.def("regime_thresholds", &thresholds, py::arg("model"), py::arg("scan"), py::arg("branch"), py::arg("axis"),
        py::arg("axis_range"));
  m.def("regime_map_defaults", &map_defaults, py::arg("params"), py::arg("branch"));
  m.def("regime_job_defaults", &job_defaults);
  m.def("frequency_band", &band, py::arg("params"), py::arg("branch"));
  m.def("lattice_model_json", &lattice_model_json, py::arg("lattice"));
  m.def("lattice_default_axis", &lattice_default_axis, py::arg("lattice"));
}

}  // namespace lrchain::python

// Regime structure (Sec. 3.3): focusing intervals with their causes, the pixel maps of Figs. 2, 4, 5
// and the boundary curves, as numpy arrays.
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "lrchain/config/option_caps.hpp"
#include "lrchain/errors.hpp"
#include "lrchain/index.hpp"
#include "lrchain/regime/boundary_curves.hpp"
#include "lrchain/regime/focusing_intervals.hpp"
#include "lrchain/regime/frequency_band.hpp"
#include "lrchain/regime/regime_map.hpp"

namespace py = pybind11;

namespace lrchain::python {

namespace {
using namespace lrchain::regime;

py::array_t<double> axis_values(const GridAxis& a) {
  py::array_t<double> v(a.n);
  for (int i = 0; i < a.n; ++i) v.mutable_at(i) = a.at(i);
  return v;
}

// Roots of the four smooth functions along (0, pi] and the focusing intervals between them.
py::dict structure(const Params& p, const std::string& branch, Index samples, double tolerance) {
  validate(p);
  const Branch b = parse_branch(branch);
  config::checked_option(double(samples), config::intervals_samples, "samples");
  if (!(tolerance > 0 && tolerance < 1e-2)) throw InvalidParameter("tolerance", "must be in (0, 1e-2)");
  RegimeStructure s;
  {
    py::gil_scoped_release release;
    s = regime_structure(regime_functions(p, b), IntervalOptions{samples, tolerance});
  }
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
  d["lo"] = lo;
  d["hi"] = hi;
  d["lo_cause"] = lo_cause;
  d["hi_cause"] = hi_cause;
  d["roots"] = roots;
  d["root_cause"] = root_cause;
  return d;
}

// Pixel values as a (y.n, x.n) int8 array with the axis values: ready for pcolormesh(x, y, values).
py::dict map_arrays(const RegimeMap& m) {
  py::array_t<std::int8_t> values({m.y.n, m.x.n});
  std::copy(m.values.begin(), m.values.end(), values.mutable_data());
  py::dict d;
  d["x"] = axis_values(m.x);
  d["y"] = axis_values(m.y);
  d["values"] = values;
  return d;
}

py::dict rho_map(const Params& base, const std::string& branch, double rho_lo, double rho_hi, Index nx,
                 double theta_lo, double theta_hi, Index ny, bool rho_log) {
  const Branch b = parse_branch(branch);
  config::checked_option(double(nx), config::map_pixels_x, "rho");  // (lo, hi, n): n pixels
  config::checked_option(double(ny), config::map_pixels_y, "theta");
  const GridAxis rho{rho_lo, rho_hi, nx, rho_log}, theta{theta_lo, theta_hi, ny};
  RegimeMap m;
  {
    py::gil_scoped_release release;
    m = theta_rho_map(base, b, rho, theta);
  }
  return map_arrays(m);
}

py::dict omega_map(const Params& base, const std::string& branch, double delta0_lo, double delta0_hi, Index nx,
                   double omega_lo, double omega_hi, Index ny, bool delta0_log) {
  const Branch b = parse_branch(branch);
  config::checked_option(double(nx), config::map_pixels_x, "delta0");  // (lo, hi, n): n pixels
  config::checked_option(double(ny), config::map_pixels_y, "omega");
  const GridAxis delta0{delta0_lo, delta0_hi, nx, delta0_log}, omega{omega_lo, omega_hi, ny};
  RegimeMap m;
  {
    py::gil_scoped_release release;
    m = delta0_omega_map(base, b, delta0, omega);
  }
  return map_arrays(m);
}

ParameterAxis parse_axis(const std::string& axis) {
  if (axis == "rho") return ParameterAxis::rho;
  if (axis == "delta0") return ParameterAxis::delta0;
  throw InvalidParameter("axis", "must be 'rho' or 'delta0', not '" + axis + "'");
}

// [(cause, points (k, 2): columns parameter, theta (or omega if omega_plane))] of every traced curve.
py::list curves(const Params& base, const std::string& branch, const std::string& axis, double lo, double hi,
                bool omega_plane) {
  validate(base);
  const Branch b = parse_branch(branch);
  const ParameterAxis a = parse_axis(axis);
  if (!(std::isfinite(lo) && std::isfinite(hi) && lo > 0 && lo < hi))
    throw InvalidParameter(axis, "range must be finite with 0 < lo < hi");
  if (omega_plane && a != ParameterAxis::delta0)
    throw InvalidParameter("omega_plane", "the omega plane goes with axis='delta0' (Figs. 4-5)");
  std::vector<BoundaryCurve> c;
  {
    py::gil_scoped_release release;
    c = boundary_curves(base, b, a, lo, hi);
    if (omega_plane) to_omega_plane(c, base, b);
  }
  py::list out;
  for (const BoundaryCurve& curve : c) {
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

py::tuple band(const Params& p, const std::string& branch) {
  validate(p);
  const FrequencyBand f = frequency_band(p, parse_branch(branch));
  return py::make_tuple(f.lo, f.hi);
}

}  // namespace

void register_regime(py::module_& m) {
  m.def("regime_structure", &structure, py::arg("params"), py::arg("branch"), py::arg("samples"),
        py::arg("tolerance"));
  m.def("theta_rho_map", &rho_map, py::arg("params"), py::arg("branch"), py::arg("rho_lo"), py::arg("rho_hi"),
        py::arg("nx"), py::arg("theta_lo"), py::arg("theta_hi"), py::arg("ny"), py::arg("rho_log"));
  m.def("delta0_omega_map", &omega_map, py::arg("params"), py::arg("branch"), py::arg("delta0_lo"),
        py::arg("delta0_hi"), py::arg("nx"), py::arg("omega_lo"), py::arg("omega_hi"), py::arg("ny"),
        py::arg("delta0_log"));
  m.def("boundary_curves", &curves, py::arg("params"), py::arg("branch"), py::arg("axis"), py::arg("lo"),
        py::arg("hi"), py::arg("omega_plane"));
  m.def("frequency_band", &band, py::arg("params"), py::arg("branch"));
}

}  // namespace lrchain::python

// Regime maps (Figs. 2, 4, 5): sign(omega'' h_tilde) on a pixel grid of the theta-rho or the
// delta0-omega plane of the resonant chain, or of the (parameter, theta) plane of any model, with
// the boundary curves and the root-found focusing bands (regime_job.hpp).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <numbers>
#include <string>

#include <fmt/format.h>

#include "lrchain/config/option_caps.hpp"
#include "lrchain/dispersion.hpp"
#include "lrchain/errors.hpp"
#include "lrchain/jobs/regime_job.hpp"
#include "lrchain/model_json.hpp"
#include "lrchain/regime/frequency_band.hpp"
#include "lrchain/regime/model_regime.hpp"
#include "lrchain/regime/regime_map.hpp"
#include "lrchain/sim/resource_estimate.hpp"
#include "regime_lattice.hpp"
#include "seconds_since.hpp"

namespace lrchain::jobs {

namespace fs = std::filesystem;
using namespace lrchain::regime;
using namespace regime_detail;

Range default_rho_range(Branch branch) { return branch == Branch::optical ? Range{0.01, 30.0} : Range{0.01, 2.5}; }

Range default_omega_range(const Params& p, Branch b, const Range& dr) {
  const FrequencyBand blo = frequency_band(with_parameter(p, ParameterAxis::delta0, dr[0]), b);
  const FrequencyBand bhi = frequency_band(with_parameter(p, ParameterAxis::delta0, dr[1]), b);
  const double wmax = std::max(blo.hi, bhi.hi);
  return {b == Branch::optical ? 0.98 * blo.lo : 0.0, 1.02 * wmax};
}

namespace {

std::vector<Branch> branches_of(const std::string& text) {
  if (text == "both") return {Branch::optical, Branch::acoustic};
  return {parse_branch(text)};
}

// A resonant_chain model's delta0-omega map runs through Params (the plane is the resonant chain's).
RegimeMapConfig through_params(const RegimeMapConfig& c) {
  if (!c.lattice.model || c.plane != "delta0-omega" || c.lattice.model->name() != "resonant_chain") return c;
  RegimeMapConfig resonant = c;
  resonant.lattice = resonant_chain_lattice(*c.lattice.model);
  return resonant;
}

// Memory, output space and the output directory of a map, checked before anything is written.
void validate_output(const RegimeMapConfig& c, double panels, const fs::path& out_dir) {
  config::checked_option(double(c.nx), config::map_pixels_x, "nx");
  config::checked_option(double(c.ny), config::map_pixels_y, "ny");
  const sim::ResourceEstimate e = sim::estimate_regime_map(double(c.nx) * double(c.ny), panels);
  sim::check_memory(e, c.max_memory, "nx", "lower nx and ny");
  if (out_dir.empty()) return;
  std::error_code ec;
  if (fs::exists(out_dir, ec) && !fs::is_directory(out_dir, ec))
    throw InputError("--out '" + out_dir.string() + "' exists and is not a directory");
  sim::check_output_space(e, out_dir, "out", "choose another --out or lower nx and ny");
}

// The resonant chain's theta-rho or delta0-omega map.
void validate_resonant(const RegimeMapConfig& c, const fs::path& out_dir) {
  const Params& p = c.lattice.params;
  validate(p);
  if (c.plane != "theta-rho" && c.plane != "delta0-omega")
    throw InvalidParameter("plane", "must be 'theta-rho' or 'delta0-omega', got '" + c.plane + "'");
  const auto branches = branches_of(c.branch);
  if (c.theta_range) check_increasing(*c.theta_range, "theta_range");
  if (c.plane == "theta-rho") {
    const Range rr = c.rho_range.value_or(Range{0.01, 30.0});
    check_increasing(rr, "rho_range");
    for (const double r : rr) {
      check_in_range(r, rho_range, "rho_range");  // each end inside rho's range (lrchain/params.hpp)
      validate(with_parameter(p, ParameterAxis::rho, r));
    }
  } else {
    const Range dr = c.delta0_range.value_or(default_delta0_range);
    check_increasing(dr, "delta0_range");
    for (const double d : dr) {
      check_in_range(d, delta0_range, "delta0_range");
      validate(with_parameter(p, ParameterAxis::delta0, d));
    }
    validate(GridAxis{dr[0], dr[1], c.nx, c.delta0_log}, "delta0");
    // Each end in [0, 2 omega_top], omega_top the top of the optical band over the delta0 range.
    double top = 0;
    for (const double d : dr)
      top = std::max(top, frequency_band(with_parameter(p, ParameterAxis::delta0, d), Branch::optical).hi);
    const Range wr = c.omega_range.value_or(Range{0.0, top});
    check_increasing(wr, "omega_range");
    for (const double w : wr)
      if (!(w >= 0 && w <= max_frequency_over_spectrum_top * top))
        throw InvalidParameter("omega_range", fmt::format("each end must be in [0, {:.6g}] ({:g} times {:.6g}, the "
                                                          "top of the optical band over the delta0 range); got {:g}",
                                                          max_frequency_over_spectrum_top * top,
                                                          max_frequency_over_spectrum_top, top, w));
  }
  validate_output(c, double(branches.size()), out_dir);
}

// A model's (parameter, theta) map.
ModelAxisPlan validate_model(const RegimeMapConfig& c, const fs::path& out_dir) {
  const Model& m = *c.lattice.model;
  if (c.plane != "theta-rho" && c.plane != "theta-parameter")
    throw InvalidParameter("plane", "with --model: 'theta-parameter' (the default; choose the parameter with --axis)" +
                                        std::string(m.name() == "resonant_chain" ? " or 'delta0-omega'" : "") +
                                        ", got '" + c.plane + "'");
  if (c.rho_range || c.delta0_range || c.omega_range || c.delta0_log || c.rho_log)
    throw InvalidParameter("axis_range", "with --model the range of the x axis is --axis-range lo hi (no --rho-range, "
                                         "--delta0-range, --omega-range, --delta0-log)");
  if (c.theta_range) check_increasing(*c.theta_range, "theta_range");
  ModelAxisPlan plan = plan_model_axis(m, c.axis, c.branch, c.axis_range);
  validate_output(c, double(plan.branches.size()), out_dir);
  return plan;
}

// A resonant-chain panel of branch b.
RegimeMapPanel resonant_panel(Branch b) {
  RegimeMapPanel panel;
  panel.branch = std::string(to_string(b));
  panel.resonant_branch = b;
  return panel;
}

// Moves a computed pixel map (RegimeMap or ModelRegimeMap) and its wall time into the panel.
template <class PixelMap>
void take_map(RegimeMapPanel& panel, PixelMap&& m, std::chrono::steady_clock::time_point started) {
  panel.map_seconds = seconds_since(started);
  panel.x = m.x;
  panel.y = m.y;
  panel.values = std::move(m.values);
}

GridAxis theta_axis(const RegimeMapConfig& c) {
  const Range t = c.theta_range.value_or(Range{std::numbers::pi / c.ny, std::numbers::pi});
  return GridAxis{t[0], t[1], c.ny};
}

// Fig. 2: one panel per branch over (rho, theta), with Fig. 2's inset of the narrow acoustic region.
void run_theta_rho(const RegimeMapConfig& c, RegimeMapResult& r) {
  const Params& p = c.lattice.params;
  for (const Branch b : branches_of(c.branch)) {
    RegimeMapPanel panel = resonant_panel(b);
    const Range rr = c.rho_range.value_or(default_rho_range(b));
    const GridAxis rho{rr[0], rr[1], c.nx, c.rho_log};
    const auto t0 = std::chrono::steady_clock::now();
    take_map(panel, theta_rho_map(p, b, rho, theta_axis(c)), t0);
    if (c.curves) {
      const auto t1 = std::chrono::steady_clock::now();
      panel.curves = boundary_curves(p, b, ParameterAxis::rho, rr[0], rr[1]);
      panel.curves_seconds = seconds_since(t1);
      panel.curves_traced = true;
    }
    if (c.inset && b == Branch::acoustic && rr[0] < 0.3 && rr[1] > 0.35) {
      const GridAxis x{std::max(rr[0], 0.04), 0.35, 300}, y{1.6, std::numbers::pi, 300};
      RegimeMap zoom = theta_rho_map(p, b, x, y);
      panel.inset_x = zoom.x;
      panel.inset_y = zoom.y;
      panel.inset_values = std::move(zoom.values);
    }
    r.panels.push_back(std::move(panel));
  }
}

// Figs. 4-5: one map per branch over (delta0, omega), with the root-found focusing bands per delta0.
void run_delta0_omega(const RegimeMapConfig& c, RegimeMapResult& r) {
  const Params& p = c.lattice.params;
  for (const Branch b : branches_of(c.branch)) {
    RegimeMapPanel panel = resonant_panel(b);
    const Range dr = c.delta0_range.value_or(default_delta0_range);
    const GridAxis delta0{dr[0], dr[1], c.nx, c.delta0_log};
    const Range wr = c.omega_range.value_or(default_omega_range(p, b, dr));
    const auto t0 = std::chrono::steady_clock::now();
    take_map(panel, delta0_omega_map(p, b, delta0, GridAxis{wr[0], wr[1], c.ny}), t0);
    if (c.bands) {
      std::vector<std::vector<FocusingInterval>> per(static_cast<std::size_t>(delta0.n));
#pragma omp parallel for schedule(dynamic)
      for (int i = 0; i < int(delta0.n); ++i)
        per[i] = focusing_intervals(with_parameter(p, ParameterAxis::delta0, delta0.at(i)), b, {1024, 1e-12});
      for (int i = 0; i < int(delta0.n); ++i) {
        const Params at_d = with_parameter(p, ParameterAxis::delta0, delta0.at(i));
        std::vector<RegimeMapPanel::Band> bands;
        for (const auto& f : per[i])
          bands.push_back({f, dispersion_omega(at_d, b, f.lo), dispersion_omega(at_d, b, f.hi)});
        panel.bands.push_back(std::move(bands));
        panel.band_edges.push_back({dispersion_omega(at_d, b, 0.0), dispersion_omega(at_d, b, std::numbers::pi)});
      }
    }
    if (c.curves) {
      const auto t1 = std::chrono::steady_clock::now();
      panel.curves = boundary_curves(p, b, ParameterAxis::delta0, dr[0], dr[1]);
      to_omega_plane(panel.curves, p, b);
      panel.curves_seconds = seconds_since(t1);
      panel.curves_traced = true;
    }
    r.panels.push_back(std::move(panel));
  }
}

// A model's (parameter, theta) map: one panel per branch of the plan.
void run_model(const RegimeMapConfig& c, const ModelAxisPlan& plan, RegimeMapResult& r) {
  const Model& m = *c.lattice.model;
  for (std::size_t k = 0; k < plan.branches.size(); ++k) {
    const Index b = plan.branches[k];
    RegimeMapPanel panel;
    panel.branch = m.definition().branch_names[static_cast<std::size_t>(b)];
    const Range& rr = plan.ranges[k];
    const auto t0 = std::chrono::steady_clock::now();
    take_map(panel, parameter_theta_map(m, b, plan.axis, GridAxis{rr[0], rr[1], c.nx}, theta_axis(c)), t0);
    if (c.curves) {
      const auto t1 = std::chrono::steady_clock::now();
      panel.curves = boundary_curves(m, b, plan.axis, rr[0], rr[1]);
      panel.curves_seconds = seconds_since(t1);
      panel.curves_traced = true;
    }
    r.panels.push_back(std::move(panel));
  }
}

}  // namespace

void validate(const RegimeMapConfig& config, const fs::path& out_dir) {
  const RegimeMapConfig c = through_params(config);
  if (c.format != "csv" && c.format != "hdf5") throw InvalidParameter("format", "must be csv or hdf5");
  if (c.lattice.model)
    validate_model(c, out_dir);
  else
    validate_resonant(c, out_dir);
}

RegimeMapResult run(const RegimeMapConfig& config) {
  const RegimeMapConfig c = through_params(config);
  RegimeMapResult r;
  r.nx = c.nx;
  r.ny = c.ny;
  r.delta0_log = c.delta0_log;
  r.curves = c.curves;
  r.figures = c.figures;
  r.format = c.format;
  if (c.lattice.model) {
    const ModelAxisPlan plan = validate_model(c, {});
    r.resonant_chain = false;
    r.axis = plan.axis;
    r.plane = "theta-" + plan.axis;
    r.model_name = c.lattice.model->name();
    r.model = model_json(*c.lattice.model);
    run_model(c, plan, r);
    return r;
  }
  validate_resonant(c, {});
  r.params = c.lattice.params;
  r.plane = c.plane;
  r.axis = c.plane == "theta-rho" ? "rho" : "delta0";
  r.model = model_json(resonant_chain_model(c.lattice.params));
  if (c.plane == "theta-rho")
    run_theta_rho(c, r);
  else
    run_delta0_omega(c, r);
  return r;
}

}  // namespace lrchain::jobs

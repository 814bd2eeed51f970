// The JSON summary of a regime map (`lrchain regime map`, regime_job.hpp).
#include <string>

#include "lrchain/jobs/regime_job.hpp"
#include "lrchain/regime/regime_map.hpp"

namespace lrchain::jobs {

using nlohmann::json;
using namespace lrchain::regime;

namespace {

// {"seconds", <cause>: number of polylines} of a panel's traced curves; {} when not traced.
json polylines_json(const RegimeMapPanel& panel) {
  json info = json::object();
  if (!panel.curves_traced) return info;
  info["seconds"] = panel.curves_seconds;
  for (BoundaryCause c : kSmoothCauses) {
    int n = 0;
    for (const auto& curve : panel.curves) n += curve.cause == c;
    info[std::string(to_string(c))] = n;
  }
  return info;
}

double focusing_fraction(const RegimeMapPanel& panel) {
  int focusing = 0;
  for (auto v : panel.values) focusing += v == PixelRegime::focusing;
  return double(focusing) / panel.values.size();
}

// Where the number of focusing bands changes along delta0 (Figs. 4-5, lower panel).
json band_count_transitions(const RegimeMapPanel& panel) {
  json transitions = json::array();
  int prev = -1;
  for (Index i = 0; i < panel.x.n && std::size_t(i) < panel.bands.size(); ++i) {
    const int n = static_cast<int>(panel.bands[i].size());
    if (n != prev)
      transitions.push_back({{"delta0_from", i > 0 ? json(panel.x.at(i - 1)) : json(nullptr)},
                             {"delta0_to", panel.x.at(i)},
                             {"focusing_bands", n}});
    prev = n;
  }
  return transitions;
}

// "png" (when figures were asked) and "files" of figure k.
void add_files(json& j, const RegimeMapFiles& files, std::size_t k) {
  if (k < files.drawn.size() && files.drawn[k]) j["png"] = *files.drawn[k];
  j["files"] = k < files.files.size() ? json(files.files[k]) : json::array();
}

}  // namespace

json to_json(const RegimeMapResult& r, const RegimeMapFiles& files) {
  const json resolution = {r.nx, r.ny};
  json out;
  if (r.resonant_chain && r.plane == "delta0-omega") {
    json maps = json::array();
    for (std::size_t k = 0; k < r.panels.size(); ++k) {
      const RegimeMapPanel& panel = r.panels[k];
      json m = {{"plane", "delta0-omega"},
                {"branch", panel.branch},
                {"delta0_range", {panel.x.lo, panel.x.hi}},
                {"omega_range", {panel.y.lo, panel.y.hi}},
                {"resolution", resolution},
                {"map_seconds", panel.map_seconds},
                {"focusing_band_count", band_count_transitions(panel)},
                {"boundary_polylines", polylines_json(panel)}};
      add_files(m, files, k);
      maps.push_back(m);
    }
    out = {{"plane", "delta0-omega"}, {"maps", maps}};
  } else {
    json panels = json::array();
    const char* range_key = r.resonant_chain ? "rho_range" : "axis_range";
    for (const RegimeMapPanel& panel : r.panels)
      panels.push_back({{"branch", panel.branch},
                        {range_key, {panel.x.lo, panel.x.hi}},
                        {"resolution", resolution},
                        {"map_seconds", panel.map_seconds},
                        {"focusing_fraction", focusing_fraction(panel)},
                        {"boundary_polylines", polylines_json(panel)}});
    out = {{"plane", r.plane}, {"panels", panels}};
    if (!r.resonant_chain) out["axis"] = r.axis;
    add_files(out, files, 0);
  }
  out["model"] = r.model;
  if (!files.hdf5.empty()) out["hdf5_files"] = files.hdf5;
  return out;
}

}  // namespace lrchain::jobs

// Structure changes of the focusing intervals along a parameter (Sec. 3.3): the paper's special mass
// ratios and precompressions, or the events along one parameter of a model: `lrchain regime
// thresholds`, lrchain.regime.thresholds (regime_job.hpp).
#include <chrono>
#include <string>

#include "lrchain/dispersion.hpp"
#include "lrchain/errors.hpp"
#include "lrchain/jobs/regime_job.hpp"
#include "lrchain/model_json.hpp"
#include "lrchain/regime/model_regime.hpp"
#include "regime_lattice.hpp"
#include "seconds_since.hpp"

namespace lrchain::jobs {

using nlohmann::json;
using namespace lrchain::regime;
using namespace regime_detail;

namespace {

ModelAxisPlan model_plan(const RegimeThresholdsConfig& c) {
  return plan_model_axis(*c.model, c.axis, c.branch.empty() ? "both" : c.branch, c.axis_range);
}

}  // namespace

void validate(const RegimeThresholdsConfig& c) {
  if (c.scan != 0 && (c.scan < 10 || c.scan > 100'000))
    throw InvalidParameter("scan", "must be in [10, 100000] (0: the built-in scan), got " + std::to_string(c.scan));
  if (!c.model) {
    if (!c.axis.empty() || c.axis_range || !c.branch.empty())
      throw InvalidParameter("model", "axis, axis_range and branch need a model (without one the paper's scenarios run)");
    return;
  }
  model_plan(c);
}

RegimeThresholdsResult run(const RegimeThresholdsConfig& c) {
  validate(c);
  RegimeThresholdsResult r;
  if (!c.model) {
    for (auto s : paper_threshold_scenarios()) {
      if (c.scan > 0) s.scan.n = c.scan;
      RegimeThresholdScan scan;
      const auto t0 = std::chrono::steady_clock::now();
      scan.events = regime_events(s.base, s.branch, s.axis, s.scan);
      scan.seconds = seconds_since(t0);
      scan.paper_values = match_paper_values(s, scan.events);
      scan.name = s.name;
      scan.branch = std::string(to_string(s.branch));
      scan.axis = std::string(to_string(s.axis));
      scan.scan = s.scan;
      scan.paper_text = s.paper_text;
      scan.model = model_json(resonant_chain_model(s.base));
      r.scans.push_back(std::move(scan));
    }
    return r;
  }
  const Model& m = *c.model;
  r.paper = false;
  r.model = model_json(m);
  const ModelAxisPlan plan = model_plan(c);
  for (std::size_t k = 0; k < plan.branches.size(); ++k) {
    const Index b = plan.branches[k];
    RegimeThresholdScan scan;
    scan.branch = m.definition().branch_names[static_cast<std::size_t>(b)];
    scan.axis = plan.axis;
    scan.scan = GridAxis{plan.ranges[k][0], plan.ranges[k][1], c.scan > 0 ? c.scan : 300};
    const auto t0 = std::chrono::steady_clock::now();
    scan.events = regime_events(m, b, plan.axis, scan.scan);
    scan.seconds = seconds_since(t0);
    r.scans.push_back(std::move(scan));
  }
  return r;
}

json to_json(const RegimeThresholdsResult& r) {
  json scans = json::array();
  for (const RegimeThresholdScan& s : r.scans) {
    json ev = json::array();
    for (const auto& e : s.events) ev.push_back(event_json(e));
    json j = {{"branch", s.branch},
              {"axis", s.axis},
              {"scan", {{"lo", s.scan.lo}, {"hi", s.scan.hi}, {"points", s.scan.n}}},
              {"events", ev},
              {"seconds", s.seconds}};
    if (r.paper) {
      json matched = json::array();
      for (const auto& m : s.paper_values) {
        json mj = {{"paper", m.paper}, {"found", m.found}};
        if (m.found) {
          mj["computed"] = m.event.value;
          mj["relative_difference"] = m.event.value / m.paper - 1.0;
          mj["event"] = event_json(m.event);
        }
        matched.push_back(mj);
      }
      j["name"] = s.name;
      j["model"] = s.model;
      j["paper_text"] = s.paper_text;
      j["paper_values"] = matched;
    }
    scans.push_back(j);
  }
  if (r.paper) return {{"scenarios", scans}};
  return {{"model", r.model}, {"scans", scans}};
}

}  // namespace lrchain::jobs

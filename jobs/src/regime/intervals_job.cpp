// The focusing theta-intervals of one branch (Sec. 3.3): `lrchain regime intervals`,
// lrchain.regime.intervals (regime_job.hpp).
#include <string>

#include "lrchain/config/option_caps.hpp"
#include "lrchain/dispersion.hpp"
#include "lrchain/errors.hpp"
#include "lrchain/jobs/regime_job.hpp"
#include "lrchain/model_json.hpp"
#include "lrchain/regime/model_regime.hpp"
#include "regime_lattice.hpp"

namespace lrchain::jobs {

using nlohmann::json;
using namespace lrchain::regime;
using namespace regime_detail;

void validate(const RegimeIntervalsConfig& c) {
  if (!c.lattice.model) validate(c.lattice.params);  // the resonant chain's own messages
  config::checked_option(double(c.samples), config::intervals_samples, "samples");
  if (!(c.tolerance > 0 && c.tolerance < 1e-2)) throw InvalidParameter("tolerance", "must be in (0, 1e-2)");
  if (!c.lattice.model) {
    parse_branch(c.branch.empty() ? "optical" : c.branch);
  } else {
    refuse_branch_without_real_frequency(*c.lattice.model, model_branch(*c.lattice.model, c.branch), c.samples);
  }
}

// The resonant chain through its specialised evaluators; a model through the generic ones.
RegimeIntervalsResult run(const RegimeIntervalsConfig& c) {
  validate(c);
  RegimeIntervalsResult r;
  r.tolerance = c.tolerance;
  const IntervalOptions options{c.samples, c.tolerance};
  if (!c.lattice.model) {
    const Branch b = parse_branch(c.branch.empty() ? "optical" : c.branch);
    r.structure = regime_structure(regime_functions(c.lattice.params, b), options);
    r.branch = std::string(to_string(b));
    r.model = model_json(resonant_chain_model(c.lattice.params));
  } else {
    const Model& m = *c.lattice.model;
    const Index b = model_branch(m, c.branch);
    r.structure = regime_structure(regime_functions(m, b), options);
    r.branch = m.definition().branch_names[static_cast<std::size_t>(b)];
    r.model = model_json(m);
  }
  return r;
}

json to_json(const RegimeIntervalsResult& r) {
  json intervals = json::array(), roots = json::array();
  for (const auto& i : r.structure.intervals) intervals.push_back(interval_json(i));
  for (const auto& root : r.structure.roots)
    roots.push_back({{"theta", root.theta}, {"cause", std::string(to_string(root.cause))}});
  return {{"branch", r.branch},
          {"model", r.model},
          {"intervals", intervals},
          {"boundaries", roots},
          {"theta_tolerance", r.tolerance}};
}

}  // namespace lrchain::jobs

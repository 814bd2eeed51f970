#pragma once
// The regime jobs' options once (option_schema.hpp): each key of RegimeIntervalsConfig,
// RegimeMapConfig, RegimeCurvesConfig and RegimeThresholdsConfig that a front end offers, with its
// default (from a default-constructed config and regime_job.hpp's default ranges), range, one-line
// documentation and the help `lrchain regime <job> --help` shows.
#include <vector>

#include "lrchain/jobs/option_schema.hpp"

namespace lrchain::jobs {

const std::vector<JobOption>& regime_intervals_options();   // `regime intervals`, lrchain.regime.intervals
const std::vector<JobOption>& regime_map_options();         // `regime map`, lrchain.regime.*_map
const std::vector<JobOption>& regime_curves_options();      // lrchain.regime.boundary_curves (Python only)
const std::vector<JobOption>& regime_thresholds_options();  // `regime thresholds`, lrchain.regime.thresholds

}  // namespace lrchain::jobs

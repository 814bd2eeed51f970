#pragma once
// What the regime jobs share (regime_job.hpp): a model's branch by name, the (parameter, theta)
// plan of a model's map or scan, and the JSON of intervals and events.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "lrchain/jobs/regime_job.hpp"

namespace lrchain::jobs::regime_detail {

// A branch of a model by name; empty: "optical" if the model has it, else its only branch.
Index model_branch(const Model& m, const std::string& name);

// Refuses (InvalidParameter("branch")) a branch with no real positive frequency at any of `samples`
// thetas in (0, pi] (omega^2 <= 0 there: an unstable lattice at these parameters).
void refuse_branch_without_real_frequency(const Model& model, Index branch, int samples);

// Refuses (InvalidParameter(key)) a range that is not lo < hi.
void check_increasing(const Range& r, const std::string& key);

// The axis, the branches and each branch's axis range of a model's (parameter, theta) map or scan.
struct ModelAxisPlan {
  std::string axis;
  std::vector<Index> branches;  // "both"/"all": every branch, optical (the highest) first
  std::vector<Range> ranges;    // per branch
};
ModelAxisPlan plan_model_axis(const Model& m, const std::string& axis, const std::string& branch,
                              const std::optional<Range>& axis_range);

nlohmann::json interval_json(const regime::FocusingInterval& i);
nlohmann::json event_json(const regime::RegimeEvent& e);

}  // namespace lrchain::jobs::regime_detail

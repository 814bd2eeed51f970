#pragma once
// How a sweep job reduces a run's result to its summary scalars: a named function per scalar, in
// the results file's order (job.cpp for the chain's simulate jobs, model_jobs.cpp for model files).
// Private to jobs/src/sweep.
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace lrchain::jobs::sweep {

template <class Result>
using Extractors = std::vector<std::pair<std::string, std::function<double(const Result&)>>>;

// The scalars' names, in order.
template <class Result>
std::vector<std::string> names_of(const Extractors<Result>& e) {
  std::vector<std::string> n;
  for (const auto& [name, f] : e) n.push_back(name);
  return n;
}

// The scalars of `r`, appended to `scalars` in order.
template <class Result>
void append_scalars(const Result& r, const Extractors<Result>& e, std::vector<double>& scalars) {
  for (const auto& [name, f] : e) scalars.push_back(f(r));
}

}  // namespace lrchain::jobs::sweep

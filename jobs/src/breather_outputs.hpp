#pragma once
// What the dark and bright breather jobs share about a model's lattice and their output directory.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "lrchain/checked_number.hpp"
#include "lrchain/errors.hpp"
#include "lrchain/model.hpp"
#include "lrchain/sim/resource_estimate.hpp"

namespace lrchain::jobs {

// Names and meanings of a model lattice's variables: strains r, w_f (translation-invariant models,
// mean_flow) or displacements u_f (on-site models), appended to `names` and `meanings`.
inline void lattice_variable_names(bool mean_flow, int fields, std::vector<std::string>& names,
                                   std::vector<std::string>& meanings) {
  for (int f = 0; f < fields; ++f) {
    names.push_back(mean_flow ? (f == 0 ? "r" : fmt::format("w{}", f)) : fmt::format("u{}", f));
    meanings.push_back(mean_flow ? (f == 0 ? "r[n] = u0[n] - u0[n-1]" : fmt::format("w{0}[n] = u{0}[n] - u0[n]", f))
                                 : fmt::format("u{}[n]", f));
  }
}

// The output directory `out` ("" : none) of a job with estimate `e`: InputError when it exists and is
// no directory, or (check_output_space) when its file system has too little room.
inline void check_output_directory(const sim::ResourceEstimate& e, const std::string& out) {
  if (out.empty()) return;
  std::error_code ec;
  if (std::filesystem::exists(out, ec) && !std::filesystem::is_directory(out, ec))
    throw InputError("--out '" + out + "' exists and is not a directory");
  sim::check_output_space(e, out, "out", "choose another --out");
}

// A continuation in the model parameter `parameter` (not omega_b) towards `to`: InvalidParameter naming
// parameter (not one of the model's) or to (missing, not finite, outside the parameter's range or at
// its present value). Shared by `dark continue` and `bright continue`.
inline void check_continued_parameter(const Model& model, const std::string& parameter, const std::optional<double>& to) {
  const auto& parameters = model.definition().parameters;
  const auto found = std::find_if(parameters.begin(), parameters.end(),
                                  [&](const ModelParameter& p) { return p.name == parameter; });
  if (found == parameters.end()) {
    std::string names = "omega_b";
    for (const auto& p : parameters) names += ", " + p.name;
    throw InvalidParameter("parameter", fmt::format("must be omega_b or a parameter of {} ({}), got '{}'",
                                                    model.name(), names, parameter));
  }
  if (!to) throw InvalidParameter("to", "is required with parameter " + parameter + " (where the continuation ends)");
  checked_finite(*to, "to");
  if (!found->contains(*to) || *to == model.parameter(parameter))
    throw InvalidParameter("to", fmt::format("must lie in the range {} of {} and differ from its value {:g}",
                                             found->range_text, parameter, model.parameter(parameter)));
}

// The perturbation of an evolve job (dark or bright): its kind, max-norm and seed, each refused naming
// its key. The seed's range is Python's, [0, 2^31): a CLI's --seed -1 arrives as 2^64 - 1.
inline void check_perturbation(const std::string& perturb, double perturb_size, std::uint64_t seed) {
  if (perturb != "none" && perturb != "unstable" && perturb != "random")
    throw InvalidParameter("perturb", "must be none, unstable or random, got '" + perturb + "'");
  if (!(std::isfinite(perturb_size) && perturb_size > 0 && perturb_size < 1))
    throw InvalidParameter("perturb_size", "must be in (0, 1) (the max-norm of the perturbation of Z(0) and Zdot(0))");
  if (seed > 2147483647) throw InvalidParameter("seed", "must be an integer in [0, 2147483647]");
}

}  // namespace lrchain::jobs

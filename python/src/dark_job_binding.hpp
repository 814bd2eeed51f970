#pragma once
// lrchain.dark's keywords -> jobs::dark::DarkConfig, and the job run without the GIL: the shared door of
// the resonant chain's calls (dark_binding.cpp) and any model's (model_dark_binding.cpp).
#include <optional>
#include <string>

#include <pybind11/pybind11.h>

#include "lrchain/jobs/dark_job.hpp"

namespace lrchain::python {

// The options every lrchain.dark call takes; an integer keyword given as a float (sites=101.0,
// samples=1e4) is accepted when integral and refused otherwise (InvalidParameter naming it).
jobs::dark::DarkConfig dark_config(jobs::dark::DarkStep step, double omega_b, const std::optional<std::string>& branch,
                                   const std::string& center, std::optional<double> sites, const std::string& mode, double tolerance,
                                   double max_iterations);
// The keywords of continue_branch (omega_max None: the band edge) and of evolve, into `c`.
void set_branch_keywords(jobs::dark::DarkConfig& c, double points, double ds, double omega_min,
                         std::optional<double> omega_max, bool floquet, const std::string& parameter,
                         std::optional<double> to);
void set_evolve_keywords(jobs::dark::DarkConfig& c, double t_end, double samples, const std::string& perturb,
                         double perturb_size, double seed);
// The integer keyword `value` (checked_integer; caps from lrchain/config/option_caps.hpp where there is one).
Index integer_keyword(double value, const std::string& keyword, std::int64_t least, std::int64_t most);

// Validates `c` and runs it without the GIL (Ctrl-C: KeyboardInterrupt, also inside an integration);
// NumericalFailure with Newton's history when Newton does not converge.
// `progress(fraction)` (None: none) is called after every branch point with points done / points, and
// after every period of an evolution with periods done / periods.
jobs::dark::DarkResult run_dark_job(const jobs::dark::DarkConfig& c, const pybind11::object& progress = pybind11::none());

}  // namespace lrchain::python

// The exact bright-breather job's option schema (bright_breather_schema.hpp): defaults read from a
// default-constructed BrightBreatherConfig.
#include "lrchain/jobs/bright_breather_schema.hpp"

#include <fmt/format.h>

#include "lrchain/config/option_caps.hpp"
#include "lrchain/jobs/bright_breather_job.hpp"

namespace lrchain::jobs::bright_breather {

namespace {

const std::vector<std::string> all_steps{"solve", "floquet", "continue"};

// A range of integers from an option cap: "[least, most]".
std::string integer_range(const config::OptionCap& cap) { return fmt::format("[{}, {}]", cap.least, cap.most); }

std::vector<JobOption> make_options() {
  const BrightBreatherConfig d;
  const nlohmann::json none;
  return {
      {"omega_b", "--omega-b", "omega_b", all_steps, none, true,
       "> 0, at most 10 times the top band, outside every band, no harmonic k omega_b inside one",
       "breather frequency omega_b (dimensionless; period T_b = 2 pi/omega_b), beyond a focusing band edge"},
      {"branch", "--branch", "branch", all_steps, d.branch.empty() ? none : nlohmann::json(d.branch), false,
       "one of the model's branches",
       "branch whose band edge the breather leaves (none: the focusing edge nearest omega_b)"},
      {"center", "--center", "center", all_steps, d.center, false, "site|bond",
       "family: site-centred (n0 = 0) or bond-centred (n0 = 1/2)"},
      {"sites", "--sites", "sites", all_steps, d.sites, false, fmt::format("odd, >= {}", config::dark_sites.least),
       "lattice sites per field (periodic ends, the centre in the middle)"},
      {"tolerance", "", "tolerance", all_steps, d.tolerance, false, "(0, 1)", "Newton: converged when max|F| <= tolerance"},
      {"max_iterations", "", "max_iterations", all_steps, d.max_iterations, false, ">= 1", "Newton iterations"},
      {"tail_tolerance", "--tail-tolerance", "tail_tolerance", all_steps, d.tail_tolerance, false, "(0, 1)",
       "localized: max |Z(0)| on the ring's far quarter at most this times the peak"},
      {"unit_tolerance", "--unit-tolerance", "unit_tolerance", {"floquet", "continue"}, d.unit_tolerance, false, "(0, 1)",
       "stable: every multiplier but the trivial +1 ones has |lambda| <= 1 + this"},
      {"points", "--points", "points", {"continue"}, d.points, false, integer_range(config::dark_points),
       "maximum number of branch points, the first included"},
      {"ds", "--ds", "ds", {"continue"}, d.ds, false, "(0, 1], adapted within [1e-5, 1]",
       "initial pseudo-arclength step in (Z(0), omega_b), dimensionless"},
      {"branch_floquet", "", "floquet", {"continue"}, d.branch_floquet, false, "true|false",
       "Floquet multipliers at every branch point"},
      {"format", "--format", "", all_steps, d.format, false, "csv|hdf5",
       "data files in --out: csv (CSV and figures) or hdf5 (also result.h5: Z(0), the seed, the branch, the summary; "
       "lrchain.load reads it)"},
      {"out", "--out", "", all_steps, d.out.empty() ? none : nlohmann::json(d.out), false, "",
       "output directory for profile.csv, multipliers.csv, summary.json and gnuplot figures (none: only the JSON on stdout)"},
  };
}

}  // namespace

const std::vector<JobOption>& bright_breather_options() { return schema_once<make_options>(); }

const JobOption& bright_breather_option(const std::string& key) { return find_option(bright_breather_options(), key); }

}  // namespace lrchain::jobs::bright_breather

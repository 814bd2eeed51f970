// The exact bright-breather job's option schema (bright_breather_schema.hpp): defaults read from a
// default-constructed BrightBreatherConfig.
#include "lrchain/jobs/bright_breather_schema.hpp"

#include <fmt/format.h>

#include "lrchain/config/option_caps.hpp"
#include "lrchain/jobs/bright_breather_job.hpp"

namespace lrchain::jobs::bright_breather {

namespace {

const std::vector<std::string> all_steps{"solve", "floquet", "continue", "evolve"};

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
      {"start", "--start", "start", all_steps, d.start, false, "nls|anti-continuum",
       "Newton's start: the NLS bright breather at the focusing edge, or (on-site models) one oscillator (two for "
       "bond) at coupling 0 continued in --coupling to its value"},
      {"coupling", "--coupling", "coupling", all_steps, d.coupling, false, "a model parameter with 0 in its range",
       "start anti-continuum: the parameter that couples the cells (set to 0, then continued to its value)"},
      {"sites", "--sites", "sites", all_steps, d.sites, false, fmt::format("odd, >= {}", config::dark_sites.least),
       "lattice sites per field (periodic ends, the centre in the middle)"},
      {"tolerance", "", "tolerance", all_steps, d.tolerance, false, "(0, 1)", "Newton: converged when max|F| <= tolerance"},
      {"max_iterations", "", "max_iterations", all_steps, d.max_iterations, false, ">= 1", "Newton iterations"},
      {"tail_tolerance", "--tail-tolerance", "tail_tolerance", all_steps, d.tail_tolerance, false, "(0, 1)",
       "localized: max |Z(0)| on the ring's far quarter at most this times the peak"},
      {"unit_tolerance", "--unit-tolerance", "unit_tolerance", {"floquet", "continue", "evolve"}, d.unit_tolerance, false, "(0, 1)",
       "stable: every multiplier but the trivial +1 ones has |lambda| <= 1 + this"},
      {"points", "--points", "points", {"continue"}, d.points, false, integer_range(config::dark_points),
       "maximum number of branch points, the first included"},
      {"ds", "--ds", "ds", {"continue"}, d.ds, false, "(0, 1], adapted within [1e-5, 1]",
       "initial pseudo-arclength step in (Z(0), omega_b), dimensionless"},
      {"locate_tolerance", "--locate-tolerance", "locate_tolerance", {"continue"}, d.locate_tolerance, false, "[0, 1)",
       "continue: each multiplier crossing bisected on re-solved breathers to a bracket this wide in the continued "
       "parameter (0: bracketed between branch points only)"},
      {"periods", "--periods", "periods", {"evolve"}, d.periods, false, "[1, 1000000]",
       "breather periods T_b integrated (the deviation and energy sampled at every multiple of T_b)"},
      {"perturb", "--perturb", "perturb", {"evolve"}, d.perturb, false, "none|unstable|random",
       "perturbation of the start: none, along the largest unstable Floquet multiplier's eigenvector, or random positions"},
      {"perturb_size", "--perturb-size", "perturb_size", {"evolve"}, d.perturb_size, false, "(0, 1)",
       "max-norm of the perturbation of [Z(0), Zdot(0)]"},
      {"seed", "--seed", "seed", {"evolve"}, d.seed, false, "[0, 2147483647]", "perturb random: the generator's seed"},
      {"parameter", "--parameter", "parameter", {"continue"}, d.parameter, false,
       "omega_b, or one of the model's parameters",
       "the continued parameter (a model parameter at fixed omega_b, e.g. C down to the anti-continuum limit 0)"},
      {"to", "--to", "to", {"continue"}, none, false,
       "a model parameter: in its range (required); omega_b: in its non-resonant window",
       "where the continuation ends, its last point solved there (omega_b: none = to the end of the window)"},
      {"solver", "--solver", "", {"solve", "floquet"}, d.krylov.solver, false, "auto|dense|krylov",
       "dense Jacobian and monodromy, or matrix-free Newton-Krylov and Arnoldi (auto: krylov above krylov_sites)"},
      {"krylov_sites", "--krylov-sites", "", {"solve", "floquet"}, d.krylov.krylov_sites, false, ">= 9",
       "solver auto: the matrix-free path above this many sites"},
      {"krylov_band", "--krylov-band", "", {"solve", "floquet"}, d.krylov.krylov_band, false, ">= 1",
       "Newton-Krylov: half-width in sites of the band-probed Jacobian that preconditions GMRES"},
      {"floquet_count", "--floquet-count", "", {"floquet"}, d.krylov.floquet_count, false, ">= 1",
       "matrix-free Floquet: the number of largest-modulus localized multipliers certified on the full lattice"},
      {"branch_floquet", "", "floquet", {"continue"}, d.branch_floquet, false, "true|false",
       "Floquet multipliers at every branch point"},
      {"format", "--format", "", all_steps, d.format, false, "csv|hdf5",
       "data files in --out: csv (CSV and figures) or hdf5 (also result.h5: Z(0), the seed, the branch, the evolution, the summary; "
       "lrchain.load reads it)"},
      {"out", "--out", "", all_steps, d.out.empty() ? none : nlohmann::json(d.out), false, "",
       "output directory for profile.csv, multipliers.csv, summary.json and gnuplot figures (none: only the JSON on stdout)"},
  };
}

}  // namespace

const std::vector<JobOption>& bright_breather_options() { return schema_once<make_options>(); }

const JobOption& bright_breather_option(const std::string& key) { return find_option(bright_breather_options(), key); }

}  // namespace lrchain::jobs::bright_breather

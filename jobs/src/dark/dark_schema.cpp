// The dark job's option schema (dark_schema.hpp): defaults read from a default-constructed DarkConfig.
#include "lrchain/jobs/dark_schema.hpp"

#include <fmt/format.h>

#include "lrchain/config/option_caps.hpp"
#include "lrchain/jobs/dark_job.hpp"

namespace lrchain::jobs::dark {

namespace {

const std::vector<std::string> all_steps{"solve", "floquet", "continue", "evolve"};

// A range of integers from an option cap: "[least, most]" or ">= least" when most is the int32 cap.
std::string integer_range(const config::OptionCap& cap, const std::string& what = "") {
  const std::string head = what.empty() ? "" : what + ", ";
  if (cap.most == config::int32_most) return fmt::format("{}>= {}", head, cap.least);
  return fmt::format("{}[{}, {}]", head, cap.least, cap.most);
}

std::vector<DarkOption> make_options() {
  const DarkConfig d;
  const nlohmann::json none;
  return {
      {"omega_b", "--omega-b", "omega_b", all_steps, none, true,
       "> 0, on the side of the edge where (omega_b - omega) h > 0: below it for the resonant chain",
       "breather frequency omega_b (dimensionless, time unit of Sec. 2; period T_b = 2 pi/omega_b)"},
      {"branch", "--branch", "branch", all_steps, d.branch.empty() ? none : nlohmann::json(d.branch), false,
       "optical|acoustic, or with a model file one of its branches",
       "branch whose band edge the breather bifurcates from (none: optical, or with a model file the first "
       "whose theta = pi edge is defocusing)"},
      {"center", "--center", "center", all_steps, d.center, false, "bond|site", "family: bond (n0 = 1/2) or site (n0 = 0)"},
      {"sites", "--sites", "sites", all_steps, none, false,
       integer_range(config::dark_sites, "odd") + " (even at a model's theta = 0 edge)",
       "lattice sites per field (periodic ends)", "",
       fmt::format("{} at a theta = pi edge, {} at theta = 0", default_dark_sites(std::numbers::pi),
                   default_dark_sites(0))},
      {"mode", "--mode", "mode", all_steps, d.mode, false, "reversible|full",
       "shooting over a half/quarter period (reversible) or the whole period (full, a check)"},
      {"tolerance", "", "tolerance", all_steps, d.tolerance, false, "(0, 1)",
       "Newton and corrector: converged when max|F| <= tolerance"},
      {"max_iterations", "", "max_iterations", all_steps, d.max_iterations, false, ">= 1", "Newton iterations"},
      {"solver", "--solver", "", {"solve", "floquet", "evolve"}, d.krylov.solver, false, "auto|dense|krylov",
       "with a model file: dense Jacobian and monodromy, or matrix-free Newton-Krylov and Arnoldi (auto: krylov above "
       "krylov_sites); the paper chain without a model file is dense"},
      {"krylov_sites", "--krylov-sites", "", {"solve", "floquet", "evolve"}, d.krylov.krylov_sites, false,
       ">= 9", "solver auto: the matrix-free path above this many sites"},
      {"krylov_band", "--krylov-band", "", {"solve", "floquet", "evolve"}, d.krylov.krylov_band, false, ">= 1",
       "Newton-Krylov: half-width in sites of the band-probed Jacobian that preconditions GMRES"},
      {"floquet_count", "--floquet-count", "", {"floquet"}, d.krylov.floquet_count, false, ">= 1",
       "matrix-free Floquet: the number of largest-modulus multipliers computed"},
      {"dark_floquet", "--dark-floquet", "", {"floquet"}, d.krylov.dark_floquet, false, "auto|window|arnoldi",
       "matrix-free Floquet at a theta = pi edge: the dip's window, certified on the full lattice, with the "
       "background's Floquet-Bloch multipliers, or restarted Arnoldi (auto: window above krylov_sites sites)"},
      {"full_monodromy", "--full-monodromy", "full_monodromy", {"floquet"}, d.full_monodromy, false,
       "not with a model file", "integrate the full period (check of the reversible reduction)"},
      {"points", "--points", "points", {"continue"}, d.points, false, integer_range(config::dark_points),
       "maximum number of branch points, the first included"},
      {"ds", "--ds", "ds", {"continue"}, d.ds, false, "(0, 1], adapted within [1e-5, 1]",
       "initial pseudo-arclength step in (Z(0), omega_b), dimensionless; with a model file the state is weighed so "
       "that it is a step of about ds/sqrt(2) in the parameter at the start"},
      {"omega_min", "--omega-min", "omega_min", {"continue"}, d.omega_min, false, "< omega_b",
       "stop when omega_b falls below this (dimensionless frequency)"},
      {"omega_max", "--omega-max", "omega_max", {"continue"}, d.omega_max, false,
       "0 (the band edge omega(pi)) or > omega_b, at most twice the top of the optical band",
       "stop when omega_b rises above this (dimensionless frequency)"},
      {"parameter", "--parameter", "parameter", {"continue"}, d.parameter, false,
       "omega_b, or with a model file one of its parameters",
       "the continued parameter (a model parameter at fixed omega_b, e.g. C down to the anti-continuum limit 0)"},
      {"to", "--to", "to", {"continue"}, none, false,
       "a model parameter: in its range (required); omega_b: > 0",
       "where the continuation ends, its last point solved there (sets the direction; omega_b: replaces omega_min "
       "or omega_max)"},
      {"branch_floquet", "", "floquet", {"continue"}, d.branch_floquet, false, "true|false",
       "Floquet multipliers at every branch point"},
      {"t_end", "--t-end", "t_end", {"evolve"}, none, true, "at least one period T_b",
       "integration time (dimensionless, time unit of Sec. 2)"},
      {"samples", "--samples", "samples", {"evolve"}, d.samples, false, integer_range(config::dark_samples),
       "samples of x_n(t) per period for the amplitudes of the position measure"},
      {"perturb", "--perturb", "perturb", {"evolve"}, d.perturb, false, "none|unstable|random",
       "start from the breather plus a perturbation: along the eigenvector of the largest Floquet multiplier "
       "(unstable) or random positions (random), to watch an instability grow"},
      {"perturb_size", "--perturb-size", "perturb_size", {"evolve"}, d.perturb_size, false, "(0, 1)",
       "max-norm of the perturbation of Z(0) and Zdot(0)"},
      {"seed", "--seed", "seed", {"evolve"}, d.seed, false, "[0, 2147483647]", "perturb random: the seed of the generator (mt19937_64)"},
      {"format", "--format", "", all_steps, d.format, false, "csv|hdf5",
       "data files in --out: csv (CSV and figures) or hdf5 (also result.h5: profiles, the branch or the evolution, "
       "Floquet multipliers as complex numbers)"},
      {"out", "--out", "", all_steps, d.out.empty() ? none : nlohmann::json(d.out), false, "",
       "output directory for CSV data and gnuplot figures (none: only the JSON on stdout)"},
  };
}

}  // namespace

const std::vector<DarkOption>& dark_options() { return schema_once<make_options>(); }

const DarkOption& dark_option(const std::string& key) { return find_option(dark_options(), key); }

}  // namespace lrchain::jobs::dark

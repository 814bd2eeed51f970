#pragma once
// --solver, --krylov-sites, --krylov-band, --floquet-count of the exact-breather commands (bright, dark
// with --model) into the job's BreatherSolverOptions (lrchain/jobs/breather_solver.hpp).
#include <CLI/CLI.hpp>
#include <limits>
#include <string>

#include "lrchain/jobs/breather_solver.hpp"
#include "options.hpp"

namespace lrchain::cli {

// help(key) is the job's help text of the schema key.
template <typename Help>
void add_solver_options(CLI::App& sub, jobs::BreatherSolverOptions& o, const Help& help) {
  sub.add_option("--solver", o.solver, help("solver"))
      ->check(CLI::IsMember({"auto", "dense", "krylov"}).description(""))
      ->type_name("auto|dense|krylov");
  constexpr std::int64_t most = std::numeric_limits<int>::max();
  add_integer(sub, "--krylov-sites", o.krylov_sites, 9, most, help("krylov_sites"));
  add_integer(sub, "--krylov-band", o.krylov_band, 1, most, help("krylov_band"));
  add_integer(sub, "--floquet-count", o.floquet_count, 1, most, help("floquet_count"));
}

}  // namespace lrchain::cli

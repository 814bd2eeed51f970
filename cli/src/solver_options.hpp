#pragma once
// --solver, --krylov-sites, --krylov-band, --floquet-count of the exact-breather commands (bright, dark
// with --model) into the job's BreatherSolverOptions (lrchain/jobs/breather_solver.hpp).
#include <CLI/CLI.hpp>
#include <algorithm>
#include <limits>
#include <string>

#include "lrchain/jobs/breather_solver.hpp"
#include "lrchain/jobs/option_schema.hpp"
#include "options.hpp"

namespace lrchain::cli {

// option(key) is the job's schema entry of the key: each option is added to the subcommands its
// steps name (e.g. --floquet-count to floquet only), with the schema's help text.
template <typename Option>
void add_solver_options(CLI::App& sub, jobs::BreatherSolverOptions& o, const Option& option) {
  const auto offered = [&](const char* key) {
    const auto& steps = option(key).steps;
    return std::find(steps.begin(), steps.end(), sub.get_name()) != steps.end();
  };
  const auto help = [&](const char* key) { return jobs::help_text(option(key)); };
  if (offered("solver"))
    sub.add_option("--solver", o.solver, help("solver"))
        ->check(CLI::IsMember({"auto", "dense", "krylov"}).description(""))
        ->type_name("auto|dense|krylov");
  constexpr std::int64_t most = std::numeric_limits<int>::max();
  if (offered("krylov_sites")) add_integer(sub, "--krylov-sites", o.krylov_sites, 9, most, help("krylov_sites"));
  if (offered("krylov_band")) add_integer(sub, "--krylov-band", o.krylov_band, 1, most, help("krylov_band"));
  if (offered("floquet_count")) add_integer(sub, "--floquet-count", o.floquet_count, 1, most, help("floquet_count"));
}

}  // namespace lrchain::cli

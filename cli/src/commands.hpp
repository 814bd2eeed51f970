#pragma once
// Registration of the `lrchain` subcommands. Each subcommand lives in its own
// <name>_command.cpp and adds itself to the app here; main.cpp calls them in order.
#include <CLI/CLI.hpp>

namespace lrchain::cli {

void register_coeffs(CLI::App& app);    // coeffs_command.cpp (NLS coefficients, eq:c..eq:h_tilde)
void register_regime(CLI::App& app);    // regime_command.cpp (focusing regimes, Sec. 3.3, Figs. 2, 4, 5)
void register_simulate(CLI::App& app);  // simulate_command.cpp (lattice runs vs NLS ansatz, Sec. 4)
void register_dark(CLI::App& app);      // dark_command.cpp (exact dark breathers, Sec. 5.3-5.4)
void register_bright(CLI::App& app);    // bright_command.cpp (exact bright breathers, docs/bright-breathers.md)
void register_reproduce(CLI::App& app); // reproduce_command.cpp (the paper's results as an HTML report)
void register_derive(CLI::App& app);    // derive_command.cpp (a model file through the multiple-scale engine)
void register_sweep(CLI::App& app);     // sweep_command.cpp (one job over a grid of parameter points)

}  // namespace lrchain::cli

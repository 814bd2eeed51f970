// `lrchain`: command-line front end. Exit codes (lrchain/exit_codes.hpp): 0 ok, 1 runtime failure,
// 2 invalid input, 3 numerical failure, 130/143 interrupted by SIGINT/SIGTERM.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <exception>
#include <string>

#include "commands.hpp"
#include "help_text.hpp"
#include "unknown_arguments.hpp"
#include "lrchain/errors.hpp"
#include "lrchain/exit_codes.hpp"
#include "lrchain/provenance.hpp"

int main(int argc, char** argv) {
  CLI::App app{
      "lrchain: nonlinear waves in one-dimensional lattices. From a model file (--model; default:\n"
      "the paper's locally resonant granular chain with precompression) it derives the NLS\n"
      "coefficients, maps the focusing regimes, runs the lattice, and finds exact dark breathers.\n"
      "The paper's chain is dimensionless as in its Sec. 2 (time in units of sqrt(m1/(A R^(alpha-1))),\n"
      "lengths in units of R). Numbers accept 0.25, 1e-3, 1/3, 3*pi/5."};
  app.require_subcommand(1);
  app.set_version_flag("--version", lrchain::version_line(), "print the lrchain version and git commit, and exit");
  app.footer(lrchain::cli::exit_codes_text());  // inherited by the subcommands, which add their examples
  lrchain::cli::register_coeffs(app);
  lrchain::cli::register_regime(app);
  lrchain::cli::register_simulate(app);
  lrchain::cli::register_dark(app);
  lrchain::cli::register_bright(app);
  lrchain::cli::register_reproduce(app);
  lrchain::cli::register_sweep(app);
#ifdef LRCHAIN_WITH_DERIVE
  lrchain::cli::register_derive(app);
#endif
  lrchain::cli::add_examples(app, {"lrchain coeffs --branch optical --theta pi/2 --rho 1/3",
                                   "lrchain reproduce --quick --out report"});
  lrchain::cli::cite_paper_numbers(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // --help exits 0; usage errors exit 2 with CLI11's one-line message.
    if (e.get_exit_code() == 0) return app.exit(e);
    // A misspelled option or subcommand is named first: CLI11 checks required options before it
    // complains about words it did not take, and the "missing" option is usually the misspelled one.
    // (Not when an option got too few values: CLI11 names that option, e.g. --rho-range 0.1 -inf.)
    const std::string unknown = e.get_name() == "ArgumentMismatch" ? "" : lrchain::cli::unknown_argument_message(app);
    if (!unknown.empty()) {
      std::fprintf(stderr, "%s\n", unknown.c_str());
      return lrchain::exit_code::invalid_input;
    }
    // A command that needs a subcommand names the ones it has.
    const std::string missing = e.get_name() == "RequiredError" ? lrchain::cli::missing_subcommand_message(app) : "";
    std::fprintf(stderr, "%s\n", missing.empty() ? ("lrchain: " + std::string(e.what())).c_str() : missing.c_str());
    return lrchain::exit_code::invalid_input;
  } catch (const lrchain::InputError& e) {
    // (an option's value is checked while the command line is read: a misspelled word wins here too)
    const std::string unknown = lrchain::cli::unknown_argument_message(app);
    std::fprintf(stderr, "%s\n", unknown.empty() ? ("lrchain: " + std::string(e.what())).c_str() : unknown.c_str());
    return lrchain::exit_code::invalid_input;
  } catch (const lrchain::NumericalFailure& e) {
    std::fprintf(stderr, "lrchain: numerical failure: %s\n", e.what());
    return lrchain::exit_code::numerical_failure;
  } catch (const lrchain::Interrupted& e) {
    std::fprintf(stderr, "lrchain: %s\n", e.what());
    return lrchain::exit_code::interrupted_base + e.signal_number();
  } catch (const std::exception& e) {
    std::fprintf(stderr, "lrchain: error: %s\n", e.what());
    return lrchain::exit_code::runtime_error;
  }
  return 0;
}

// `lrchain`: command-line front end. Exit codes (lrchain/exit_codes.hpp): 0 ok, 1 runtime failure,
// 2 invalid input, 3 numerical failure, 130/143 interrupted by SIGINT/SIGTERM.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <exception>

#include "commands.hpp"
#include "lrchain/errors.hpp"
#include "lrchain/exit_codes.hpp"
#include "lrchain/provenance.hpp"

int main(int argc, char** argv) {
  CLI::App app{
      "lrchain: breathers in a locally resonant granular chain with precompression.\n"
      "All quantities are dimensionless as in Sec. 2 of the paper (time in units of\n"
      "sqrt(m1/(A R^(alpha-1))), lengths in units of R). Numbers accept 0.25, 1e-3, 1/3, 3*pi/5."};
  app.require_subcommand(1);
  app.set_version_flag("--version", lrchain::version_line(), "print the lrchain version and git commit, and exit");
  app.footer(
      "Exit codes: 0 success; 1 another error (e.g. a file could not be written); 2 bad input or a\n"
      "job too large for the machine (one line on stderr names the option; nothing written);\n"
      "3 numerical failure (blow-up of a lattice run, Newton not converging; also in the JSON);\n"
      "130/143 interrupted by SIGINT/SIGTERM.");
  lrchain::cli::register_coeffs(app);
  lrchain::cli::register_regime(app);
  lrchain::cli::register_simulate(app);
  lrchain::cli::register_dark(app);
  lrchain::cli::register_reproduce(app);
  lrchain::cli::register_sweep(app);
#ifdef LRCHAIN_WITH_DERIVE
  lrchain::cli::register_derive(app);
#endif
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // --help exits 0; usage errors exit 2 with CLI11's one-line message.
    if (e.get_exit_code() == 0) return app.exit(e);
    std::fprintf(stderr, "lrchain: %s\n", e.what());
    return lrchain::exit_code::invalid_input;
  } catch (const lrchain::InputError& e) {
    std::fprintf(stderr, "lrchain: %s\n", e.what());
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

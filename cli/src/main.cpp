// `lrchain`: command-line front end. Exit codes: 0 ok, 2 invalid input, 1 runtime failure.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <exception>

#include "commands.hpp"
#include "lrchain/errors.hpp"

int main(int argc, char** argv) {
  CLI::App app{
      "lrchain: breathers in a locally resonant granular chain with precompression.\n"
      "All quantities are dimensionless as in Sec. 2 of the paper (time in units of\n"
      "sqrt(m1/(A R^(alpha-1))), lengths in units of R). Numbers accept 0.25, 1e-3, 1/3, 3*pi/5."};
  app.require_subcommand(1);
  lrchain::cli::register_coeffs(app);
  lrchain::cli::register_regime(app);
  lrchain::cli::register_simulate(app);
  lrchain::cli::register_dark(app);
  lrchain::cli::register_reproduce(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // --help exits 0; usage errors exit 2 with CLI11's one-line message.
    if (e.get_exit_code() == 0) return app.exit(e);
    std::fprintf(stderr, "lrchain: %s\n", e.what());
    return 2;
  } catch (const lrchain::InvalidParameter& e) {
    std::fprintf(stderr, "lrchain: invalid %s\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "lrchain: error: %s\n", e.what());
    return 1;
  }
  return 0;
}

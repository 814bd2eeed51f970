// `lrchain coeffs`: argv -> jobs::CoeffsConfig, jobs::CoeffsResult -> text or JSON on stdout
// (the job: lrchain/jobs/coeffs.hpp).
#include <cstdio>
#include <fmt/core.h>
#include <memory>
#include <string>
#include <string_view>

#include "commands.hpp"
#include "help_text.hpp"
#include "lrchain/errors.hpp"
#include "lrchain/jobs/coeffs.hpp"
#include "lrchain/jobs/coeffs_hdf5.hpp"
#include "model_option.hpp"
#include "options.hpp"

namespace lrchain::cli {
namespace {

struct CoeffsOptions {
  Params params;
  ModelSelection model;
  double theta = 0;
  std::string branch;
  bool json = false;
  bool table = false;
  std::string out;
};

// The help of a CoeffsConfig key: its documentation, range and default (coeffs_options()).
std::string help_of(const std::string& key) { return jobs::help_text(jobs::find_option(jobs::coeffs_options(), key)); }

}  // namespace

void register_coeffs(CLI::App& app) {
  auto opts = std::make_shared<CoeffsOptions>();
  auto* cmd = app.add_subcommand(
      "coeffs",
      "NLS coefficients of the modulation equations (Sec. 3): omega, group velocity c, curvature omega'',\n"
      "gamma, beta, h, lambda, h_tilde = h - lambda beta, the two non-resonance values and the regime\n"
      "(focusing if omega'' h_tilde < 0). Dimensionless units of Sec. 2.");
  add_number(*cmd, "--theta", opts->theta, help_of("theta"));
  add_model_options(*cmd, opts->params, /*rho_required=*/false);
  add_model_file_options(*cmd, opts->model);
  cmd->add_option("--branch", opts->branch, help_of("branch"))->type_name("NAME");
  cmd->add_flag("--json", opts->json, help_of("format"));
  cmd->add_flag("--table", opts->table, help_of("table"));
  cmd->add_option("--out", opts->out, help_of("out"))->type_name("DIR");
  add_examples(*cmd, {"lrchain coeffs --branch optical --theta pi/2 --rho 1/3",
                      "lrchain coeffs --branch acoustic --theta 3*pi/5 --rho 1 --json",
                      "lrchain coeffs --table --rho 10", "lrchain coeffs --table --json",
                      "lrchain coeffs --branch optical --theta 1 --out out/coeffs"});
  cmd->callback([opts, cmd] {
    if (opts->table)  // the table has its own wavenumbers and every branch
      for (const char* name : {"--theta", "--branch"})
        if (cmd->count(name) > 0)
          throw InputError(std::string(name) + " is not used with --table (it lists every branch at theta = pi/8 ... pi)");
    if (opts->model.file.empty()) validate(opts->params);  // --alpha ... --rho: the resonant chain's own messages
    jobs::CoeffsConfig config;
    config.model = load_selected_model(opts->model, *cmd, opts->params);  // --model, --set and the aliases
    config.branch = opts->branch;
    if (cmd->count("--theta") > 0) config.theta = opts->theta;
    config.table = opts->table;
    config.format = opts->json ? jobs::CoeffsFormat::json : jobs::CoeffsFormat::text;
    config.out = opts->out;
    const jobs::CoeffsResult result = jobs::run_coeffs(config);
    if (!config.out.empty()) jobs::write(result, config.out);
    if (config.format == jobs::CoeffsFormat::json) std::printf("%s\n", jobs::to_json(result).dump().c_str());
    else fmt::print("{}", jobs::to_text(result, &report::plain_citations));
  });
}

}  // namespace lrchain::cli

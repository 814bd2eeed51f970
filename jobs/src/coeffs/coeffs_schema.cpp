// The coefficients job's option schema (coeffs.hpp): the help `lrchain coeffs --help` shows,
// "doc: range (default: D)".
#include "lrchain/jobs/coeffs.hpp"

namespace lrchain::jobs {

namespace {

constexpr const char* coeffs_help = "{doc}: {range} (default: {default})";

std::vector<JobOption> make_options() {
  const CoeffsConfig d;
  const nlohmann::json none;
  const std::string one_wavenumber = "none (required for one wavenumber)";
  return {
      // (--model and --set are the model loader's options: model_option.hpp)
      {"model", "", "", {}, none, false, "a shipped model or a model file (docs/models.md)",
       "lattice model with its parameter values", coeffs_help, "the resonant chain"},
      {"params", "", "params", {}, none, false, "the ranges of lrchain/params.hpp", "the resonant chain's parameters",
       coeffs_help, "alpha=3/2, delta0=4/9, kappa=1, rho=1/3"},
      {"branch", "--branch", "branch", {}, none, false,
       "optical (omega_+) or acoustic (omega_-); other models: the names `lrchain derive` lists (acoustic/optical or "
       "branch0, branch1, ...), by default a model's only branch",
       "dispersion branch", coeffs_help, one_wavenumber},
      {"theta", "--theta", "theta", {}, none, false, "in (-pi, pi], nonzero on an acoustic branch",
       "carrier wavenumber, e.g. pi/2", coeffs_help, one_wavenumber},
      {"table", "--table", "", {}, d.table, false, "true or false",
       "the table of every branch at theta = pi/8 ... pi instead of one wavenumber", coeffs_help},
      {"format", "--json", "", {}, d.format == CoeffsFormat::json ? "json" : "text", false, "text or json",
       "text, or one JSON object on one line: theta, branch, the coefficients (singular ones as null), the model with "
       "its parameter values, provenance; with the table every branch's rows",
       std::string(coeffs_help) + " (--json: JSON)"},
      {"out", "--out", "", {}, none, false, "a directory (created)",
       "also write the coefficients as HDF5 in this directory: result.h5, with --table result_<branch>.h5 "
       "(lrchain.load reads them)", coeffs_help, "none: only stdout"},
  };
}

}  // namespace

const std::vector<JobOption>& coeffs_options() { return schema_once<make_options>(); }

}  // namespace lrchain::jobs

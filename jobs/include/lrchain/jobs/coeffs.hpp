#pragma once
// The coefficients job (`lrchain coeffs`, lrchain.coefficients_scalar): the NLS coefficients of the
// modulation equations (eq:c, eq:ppOmega, eq:gamma, eq:h, eq:lambda, eq:h_tilde) of one branch at one
// wavenumber, or the table of every branch at theta = pi/8 ... pi. Any model; the resonant chain
// through its specialised evaluators (lib chooses them: Model::resonant_chain_params).
// CoeffsConfig -> validate -> run_coeffs -> CoeffsResult -> to_json / to_text.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "lrchain/coefficients.hpp"
#include "lrchain/jobs/option_schema.hpp"
#include "lrchain/model.hpp"
#include "lrchain/params.hpp"

namespace lrchain::jobs {

// How a front end shows the result: text for a reader, or one JSON object on one line.
enum class CoeffsFormat { text, json };

struct CoeffsConfig {
  std::optional<Model> model;    // the lattice with its parameter values; empty: the resonant chain at `params`
  Params params;                 // the resonant chain's alpha, delta0, kappa, rho (used when `model` is empty)
  std::string branch;            // branch name; required for one wavenumber, not used with `table`
  std::optional<double> theta;   // carrier wavenumber in (-pi, pi]; required for one wavenumber, not used with `table`
  bool table = false;            // every branch at theta = pi/8, pi/4, pi/2, 3pi/5, 3pi/4, pi instead
  CoeffsFormat format = CoeffsFormat::text;  // text, or one JSON object on one line
  std::string out;               // directory for the HDF5 file(s) (coeffs_hdf5.hpp); "": none
};

// Every key of CoeffsConfig with its default, range and one line of documentation (option_schema.hpp):
// what the CLI's help and the Python docstrings show (each front end spells the key its own way).
const std::vector<JobOption>& coeffs_options();

// One branch of the table: its coefficients at table_thetas() (coefficients_batch).
struct CoeffsTableBranch {
  std::string name;
  bool mean_flow = true;  // false: on-site model, no lambda
  std::vector<NlsCoefficients> rows;
};

struct CoeffsResult {
  Model model;                       // the model evaluated, with its parameter values
  std::string branch;                // one wavenumber: the branch's name
  NlsCoefficients coefficients;      // one wavenumber: its coefficients
  std::vector<CoeffsTableBranch> table;  // table: every branch, the highest first
  bool is_table = false;
};

// The table's wavenumbers with their labels: pi/8, pi/4, pi/2, 3pi/5, 3pi/4, pi.
struct LabelledWavenumber {
  const char* label;
  double theta;
};
const std::vector<LabelledWavenumber>& table_thetas();

// Throws InvalidParameter naming the CoeffsConfig key (the resonant chain's parameters by name:
// "rho", ...): parameters out of range, theta or branch missing for one wavenumber.
void validate(const CoeffsConfig& config);

// validate(), then the coefficients (lrchain::coefficients / coefficients_batch): InvalidParameter
// for a wavenumber or branch the model refuses.
CoeffsResult run_coeffs(const CoeffsConfig& config);

// One wavenumber: {"theta", "omega", ..., "regime", "branch", "model", "provenance"}; the table:
// {"model", "branches": [{"branch", "rows": [coefficients with "theta_label"]}], "provenance"}.
// Non-finite values (singular coefficients, an on-site model's lambda) are null.
nlohmann::json to_json(const CoeffsResult& result);

// The text a reader sees; `cite` renders the equation labels in a text (e.g. "eq:disp1d") as the front end
// shows citations (the CLI: the compiled paper's numbers).
std::string to_text(const CoeffsResult& result, std::string (*cite)(const std::string& text));

}  // namespace lrchain::jobs

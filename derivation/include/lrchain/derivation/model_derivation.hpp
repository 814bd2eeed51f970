#pragma once
// A model file through the engine: derivation, branches at the chosen parameter values, and the
// checks every model must pass (a failing check fails the derivation), with their report.
#include <memory>
#include <string>
#include <vector>

#include "lrchain/derivation/branches.hpp"
#include "lrchain/derivation/model_file.hpp"
#include "lrchain/derivation/multiscale.hpp"
#include "lrchain/derivation/paper_checks.hpp"

namespace lrchain::derivation {

struct ModelDerivation {
  ModelFile file;
  GiNaC::exmap values;               // parameter and named-intermediate values used for branches/checks
  DerivedCoefficients coefficients;  // refers to file.model: keep this object where it is
  std::vector<BranchInfo> branches;
  std::vector<CheckResult> checks;
  double derive_seconds = 0, check_seconds = 0;
  bool passed() const;
};

// Derives `file` (lrchain::InputError when the engine cannot treat the model or it has no real
// branch at `values`), finds its branches and runs its checks.
std::unique_ptr<ModelDerivation> derive_model(ModelFile file, const GiNaC::exmap& values, const Symbols& s);

// The checks: c and omega'' against implicit differentiation of det M = 0, invariance under a
// rescaled left kernel, the d_xi A_{2,1} coefficient vanishing, and the reference checks below.
std::vector<CheckResult> run_model_checks(const ModelDerivation& m, const Symbols& s);

// Checks for the shipped models with known answers: resonant_chain and homogeneous_chain equal the
// C++ reference derivation (and the paper's closed forms); fput equals homogeneous_chain with
// K2 = 1, K3 = a, K4 = b. Empty for other names.
std::vector<CheckResult> reference_checks(const ModelDerivation& m, const Symbols& s);

// The derivation's text report: case, branches, intermediates, coefficients (plain or LaTeX), checks.
std::string model_report(const ModelDerivation& m, const Symbols& s, bool latex);

// The derived coefficients in the named-intermediate form (name, expression), in derivation order.
std::vector<std::pair<std::string, GiNaC::ex>> symbolic_coefficients(const ModelDerivation& m, const Symbols& s);

}  // namespace lrchain::derivation

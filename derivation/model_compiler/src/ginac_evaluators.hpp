#pragma once
// A derived model's evaluators computed by GiNaC (evalf): the fallback for a user model when no
// C++ compiler is available. The same expressions as the emitted C++ (model_evaluator_definitions),
// substituted and evaluated per call; nls() from consistent inputs at 40 digits, as the emitted
// extended-precision nls. Each call holds the process-wide symbolic_engine_mutex().
#include <ginac/ginac.h>

#include <mutex>
#include <string>
#include <vector>

#include "lrchain/derivation/model_derivation.hpp"
#include "lrchain/derivation/symbolic_lock.hpp"
#include "lrchain/model.hpp"

namespace lrchain {

class GinacModelEvaluators final : public ModelEvaluatorObject {
 public:
  GinacModelEvaluators(const derivation::ModelDerivation& m, const derivation::Symbols& s);
  // Releases the expressions under the lock (their reference counts are GiNaC's shared state).
  ~GinacModelEvaluators() override;
  void intermediates(const double* parameters, double* q) const override;
  void dispersion(double D1, double sigma, const double* q, double* coefficients) const override;
  void nls(double D1, double sigma, double omega, const double* q, double* out) const override;
  void harmonics(double D1, double sigma, double omega, const double* q, double* out) const override;

  // Where an input is read from or an output written to: p[i], q[i], w[i], out[i], D1, sigma, omega.
  struct Slot {
    char array = 0;  // 'p', 'q', 'w', 'o', or 'D' (D1), 's' (sigma), 'm' (omega)
    int index = 0;
  };
  struct Output {
    Slot slot;
    GiNaC::ex value;                     // the expression (not used for a term scale)
    bool term_scale = false;             // sum |terms of the numerator| / |denominator|
    GiNaC::exvector terms;               // numerator terms of a term scale
    GiNaC::ex denominator;               // its denominator
    GiNaC::ex symbol;                    // stands for this output in later ones (0 if none)
  };
  struct Function {
    std::vector<std::pair<GiNaC::ex, Slot>> inputs;
    std::vector<Output> outputs;
  };
  // The values one call reads and writes.
  struct Arrays {
    const double* p = nullptr;
    const double* q_in = nullptr;
    double D1 = 0, sigma = 0, omega = 0;
    double* q_out = nullptr;
    double* w = nullptr;
    double* out = nullptr;
  };

 private:
  void run(const Function& f, const Arrays& a) const;
  void evaluate_outputs(const Function& f, GiNaC::exmap& values, const Arrays& a, bool keep_precision) const;
  void run_consistent(const Function& f, double D1, double sigma, double omega, const double* q, double* out) const;

  Function intermediates_, dispersion_, nls_, harmonics_;
  std::size_t parameter_count_ = 0;
};

}  // namespace lrchain

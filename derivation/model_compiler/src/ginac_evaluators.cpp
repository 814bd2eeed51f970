#include "ginac_evaluators.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

#include "lrchain/derivation/evaluate.hpp"
#include "lrchain/derivation/model_emission.hpp"

namespace lrchain {

using namespace GiNaC;

namespace {

// "q[12]" -> {'q', 12}; "out[3]" -> {'o', 3}; "D1", "sigma", "omega" -> scalars.
GinacModelEvaluators::Slot parse_slot(const std::string& name) {
  if (name == "D1") return {'D', 0};
  if (name == "sigma") return {'s', 0};
  if (name == "omega") return {'m', 0};
  const auto open = name.find('[');
  if (open == std::string::npos || name.back() != ']') throw std::logic_error("unknown evaluator slot " + name);
  const std::string array = name.substr(0, open);
  const int index = std::stoi(name.substr(open + 1));
  if (array == "p") return {'p', index};
  if (array == "q") return {'q', index};
  if (array == "w") return {'w', index};
  if (array == "out") return {'o', index};
  throw std::logic_error("unknown evaluator slot " + name);
}

// The emitter's description of one function, prepared for substitution.
GinacModelEvaluators::Function prepare(const derivation::EmittedFunction& f) {
  GinacModelEvaluators::Function out;
  for (const auto& [symbol, name] : f.inputs) out.inputs.emplace_back(symbol, parse_slot(name));
  for (const auto& [name, e] : f.outputs) {
    GinacModelEvaluators::Output o;
    o.slot = parse_slot(name);
    o.value = e;
    const auto s = f.output_symbols.find(name);
    o.symbol = s == f.output_symbols.end() ? ex(0) : s->second;
    if (f.term_scales.count(name)) {  // as emit_cpp's term_scale_tree
      o.term_scale = true;
      const ex nd = normal(e).numer_denom();
      const ex numerator = expand(nd.op(0));
      if (is_a<add>(numerator))
        for (const auto& t : numerator) o.terms.push_back(t);
      else
        o.terms.push_back(numerator);
      o.denominator = nd.op(1);
    }
    out.outputs.push_back(std::move(o));
  }
  return out;
}

// Significant digits of the nls() evaluation: more than the compiled path's long double or
// __float128, so the fallback is at least as accurate.
constexpr int kNlsDigits = 40;

// An exact double as a kNlsDigits-digit number (a double-float numeric would keep the whole
// computation in double: CLN rounds mixed precisions to the smaller one).
numeric precise(double x) { return ex_to<numeric>(evalf(derivation::exact(x))); }

// A real double from an evaluated expression; NaN if it did not evaluate to a number.
double to_double(const ex& e) {
  const ex v = e.evalf();
  if (!is_a<numeric>(v)) return std::numeric_limits<double>::quiet_NaN();
  return ex_to<numeric>(v).real().to_double();
}

double read(const GinacModelEvaluators::Slot& s, const GinacModelEvaluators::Arrays& a) {
  switch (s.array) {
    case 'p': return a.p[s.index];
    case 'q': return a.q_in[s.index];
    case 'D': return a.D1;
    case 's': return a.sigma;
    case 'm': return a.omega;
  }
  throw std::logic_error("not an input slot");
}

double& write(const GinacModelEvaluators::Slot& s, const GinacModelEvaluators::Arrays& a) {
  switch (s.array) {
    case 'q': return a.q_out[s.index];
    case 'w': return a.w[s.index];
    case 'o': return a.out[s.index];
  }
  throw std::logic_error("not an output slot");
}

}  // namespace

GinacModelEvaluators::GinacModelEvaluators(const derivation::ModelDerivation& m, const derivation::Symbols& s)
    : parameter_count_(m.file.parameters.size()) {
  const auto functions = derivation::model_evaluator_definitions(m, s);
  intermediates_ = prepare(functions.at(0));
  dispersion_ = prepare(functions.at(1));
  nls_ = prepare(functions.at(2));
  harmonics_ = prepare(functions.at(3));
}

GinacModelEvaluators::~GinacModelEvaluators() {
  const std::lock_guard<std::recursive_mutex> lock(derivation::symbolic_engine_mutex());
  intermediates_ = {};
  dispersion_ = {};
  nls_ = {};
  harmonics_ = {};
}

// Inputs and earlier outputs substituted as double-precision numbers, each output evaluated by evalf.
void GinacModelEvaluators::run(const Function& f, const Arrays& a) const {
  const std::lock_guard<std::recursive_mutex> lock(derivation::symbolic_engine_mutex());
  exmap values;
  for (const auto& [symbol, slot] : f.inputs) values[symbol] = numeric(read(slot, a));
  evaluate_outputs(f, values, a, false);
}

// Each output evaluated by evalf with `values` substituted; later outputs see earlier ones at
// full precision when `keep_precision`, else rounded to double.
void GinacModelEvaluators::evaluate_outputs(const Function& f, exmap& values, const Arrays& a, bool keep_precision) const {
  for (const auto& o : f.outputs) {
    ex precise_value;
    bool evaluated = false;
    double v = 0;
    try {
      if (o.term_scale) {
        for (const auto& t : o.terms) v += std::abs(to_double(t.subs(values)));
        if (!o.denominator.is_equal(1)) v /= std::abs(to_double(o.denominator.subs(values)));
      } else {
        precise_value = evalf(o.value.subs(values));
        v = to_double(precise_value);
        evaluated = is_a<numeric>(precise_value);
      }
    } catch (const std::exception&) {  // division by zero, pole of a function
      v = std::numeric_limits<double>::quiet_NaN();
    }
    write(o.slot, a) = v;
    if (!o.symbol.is_zero())
      values[o.symbol] = keep_precision && evaluated ? precise_value : ex(numeric(v));
  }
}

void GinacModelEvaluators::intermediates(const double* parameters, double* q) const {
  for (std::size_t i = 0; i < parameter_count_; ++i) q[i] = parameters[i];
  Arrays a;
  a.p = parameters;
  a.q_out = q;
  run(intermediates_, a);
}

void GinacModelEvaluators::dispersion(double D1, double sigma, const double* q, double* coefficients) const {
  Arrays a;
  a.q_in = q;
  a.D1 = D1;
  a.sigma = sigma;
  a.w = coefficients;
  run(dispersion_, a);
}

void GinacModelEvaluators::nls(double D1, double sigma, double omega, const double* q, double* out) const {
  run_consistent(nls_, D1, sigma, omega, q, out);
}

void GinacModelEvaluators::harmonics(double D1, double sigma, double omega, const double* q, double* out) const {
  run_consistent(harmonics_, D1, sigma, omega, q, out);
}

// As the emitted extended-precision nls (model_emission.cpp): the intermediates recomputed from the
// parameters, (D1, sigma) rescaled so that sin^2 + cos^2 = 1 for the half angle, omega^2 polished
// on det M = 0, then every output of f (nls or harmonics) at kNlsDigits digits.
void GinacModelEvaluators::run_consistent(const Function& f, double D1, double sigma, double omega, const double* q,
                                          double* out) const {
  const std::lock_guard<std::recursive_mutex> lock(derivation::symbolic_engine_mutex());
  struct DigitsScope {  // restores GiNaC's global precision on every exit
    long saved = Digits;
    ~DigitsScope() { Digits = saved; }
  } scope;
  Digits = kNlsDigits;
  exmap parameters;
  for (const auto& [symbol, slot] : intermediates_.inputs) parameters[symbol] = precise(q[slot.index]);
  std::vector<ex> q_values(parameter_count_ + intermediates_.outputs.size());
  for (std::size_t i = 0; i < parameter_count_; ++i) q_values[i] = precise(q[i]);
  for (const auto& o : intermediates_.outputs) q_values.at(std::size_t(o.slot.index)) = evalf(o.value.subs(parameters));
  numeric d1 = precise(D1), s = precise(sigma);
  if (D1 > 0) {
    const numeric norm = d1 / 4 + s * s / d1;
    d1 = d1 / norm;
    s = s / norm;
  }
  exmap values;
  for (const auto& [symbol, slot] : f.inputs) {
    if (slot.array == 'q') values[symbol] = q_values.at(std::size_t(slot.index));
    else if (slot.array == 'D') values[symbol] = d1;
    else if (slot.array == 's') values[symbol] = s;
  }
  std::vector<numeric> w;
  for (const auto& o : dispersion_.outputs) {
    const ex c = evalf(o.value.subs(values));
    w.push_back(is_a<numeric>(c) ? ex_to<numeric>(c).real() : numeric(0));
  }
  numeric w2 = precise(omega) * precise(omega);
  for (int iteration = 0; iteration < 4; ++iteration) {
    numeric p = 0, dp = 0;
    for (std::size_t k = w.size(); k-- > 0;) {
      dp = dp * w2 + p;
      p = p * w2 + w[k];
    }
    if (dp.is_zero()) break;
    const numeric step = p / dp;
    if (abs(step) > numeric(1, 1000000) * abs(w2)) break;
    w2 -= step;
  }
  for (const auto& [symbol, slot] : f.inputs)
    if (slot.array == 'm') values[symbol] = w2.is_positive() ? ex_to<numeric>(evalf(sqrt(w2))) : precise(omega);
  Arrays a;
  a.out = out;
  evaluate_outputs(f, values, a, true);
}

}  // namespace lrchain

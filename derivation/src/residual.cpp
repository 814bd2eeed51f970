#include "lrchain/derivation/residual.hpp"
#include "lrchain/derivation/derivation_stop.hpp"

#include <array>
#include <stdexcept>

namespace lrchain::derivation {

using namespace GiNaC;

namespace {

// Truncated power series in eps: coefficient of eps^0 .. eps^kMaxOrder.
using Series = std::array<ex, kMaxOrder + 1>;

Series constant(const ex& e) { return {e, 0, 0, 0}; }

Series add_series(const Series& a, const Series& b) {
  Series r;
  for (int i = 0; i <= kMaxOrder; ++i) r[i] = a[i] + b[i];
  return r;
}

Series multiply(const Series& a, const Series& b) {
  Series r{0, 0, 0, 0};
  for (int i = 0; i <= kMaxOrder; ++i)
    for (int k = 0; i + k <= kMaxOrder; ++k)
      if (!a[i].is_zero() && !b[k].is_zero()) r[i + k] += expand(a[i] * b[k]);
  return r;
}

// Carrier phase z^n with z = e^{i theta} = (1 - D1/2) + i sigma (a lattice shift n -> n+m of E^j is z^{jm}).
ex carrier_phase(const Symbols& s, int n) {
  const ex z = (1 - s.D1 / 2) + I * s.sigma;
  const ex zbar = (1 - s.D1 / 2) - I * s.sigma;
  return n >= 0 ? pow(z, n) : pow(zbar, -n);
}

// Field f at site n+m: sum_k eps^k sum_j E^j z^{jm} A_{k,j}(tau, xi + eps m), Taylor-expanded in eps m.
Series shifted_field(const Symbols& s, Jets& jets, int f, int m) {
  Series r{0, 0, 0, 0};
  for (int k = 1; k <= kMaxOrder; ++k)
    for (int j = -k; j <= k; ++j) {
      const ex phase = carrier_phase(s, j * m);
      ex mq = 1;  // m^q / q!
      for (int q = 0; k + q <= kMaxOrder; ++q) {
        if (q > 0) mq = mq * m / q;
        if (mq.is_zero()) break;
        r[k + q] += expand(mq * phase * pow(s.E, j) * jets.get(f, k, j, 0, q));
      }
    }
  return r;
}

// Evaluates a polynomial in shift symbols with their series substituted (truncated products).
Series evaluate(const ex& e, const std::map<ex, Series, ex_is_less>& fields) {
  poll_derivation_stop();  // once per term and factor of a force
  if (auto it = fields.find(e); it != fields.end()) return it->second;
  if (is_a<GiNaC::add>(e)) {
    Series r{0, 0, 0, 0};
    for (const auto& term : e) r = add_series(r, evaluate(term, fields));
    return r;
  }
  if (is_a<mul>(e)) {
    Series r = constant(1);
    for (const auto& factor : e) r = multiply(r, evaluate(factor, fields));
    return r;
  }
  if (is_a<power>(e) && e.op(1).info(info_flags::posint)) {
    const Series base = evaluate(e.op(0), fields);
    Series r = constant(1);
    for (int i = 0; i < ex_to<numeric>(e.op(1)).to_int(); ++i) r = multiply(r, base);
    return r;
  }
  for (const auto& [sym, series] : fields)
    if (e.has(sym)) throw std::runtime_error("model rhs is not a polynomial in the shifted fields");
  return constant(e);
}

// d^2/dt^2 of field f: each A_{k,j} E^j is hit twice by (eps^2 d_tau - eps c d_xi - i j omega).
Series second_time_derivative(const Symbols& s, Jets& jets, int f) {
  struct Term { int order; ex coeff; int p, q; };
  Series r{0, 0, 0, 0};
  for (int k = 1; k <= kMaxOrder; ++k)
    for (int j = -k; j <= k; ++j) {
      std::vector<Term> terms{{k, 1, 0, 0}};
      for (int pass = 0; pass < 2; ++pass) {
        std::vector<Term> next;
        for (const Term& t : terms) {
          next.push_back({t.order, t.coeff * (-I * j * s.omega), t.p, t.q});
          next.push_back({t.order + 1, t.coeff * (-s.c), t.p, t.q + 1});
          next.push_back({t.order + 2, t.coeff, t.p + 1, t.q});
        }
        terms = std::move(next);
      }
      for (const Term& t : terms)
        if (t.order <= kMaxOrder) r[t.order] += t.coeff * pow(s.E, j) * jets.get(f, k, j, t.p, t.q);
    }
  return r;
}

}  // namespace

ex reduce_trig(const ex& e, const Symbols& s) {
  return expand(expand(e).subs(pow(s.sigma, 2) == s.D1 - pow(s.D1, 2) / 4, subs_options::algebraic));
}

Residual build_residual(const LatticeDescription& model, const Symbols& s, Jets& jets) {
  std::map<ex, Series, ex_is_less> fields;
  for (std::size_t f = 0; f < model.fields.size(); ++f)
    for (int m = -3; m <= 3; ++m) fields[model.shift(f, m)] = shifted_field(s, jets, int(f), m);

  Residual res(model.fields.size());
  for (std::size_t f = 0; f < model.fields.size(); ++f) {
    const Series rhs = evaluate(model.rhs[f], fields);
    const Series acc = second_time_derivative(s, jets, int(f));
    res[f].resize(kMaxOrder + 1);
    for (int k = 0; k <= kMaxOrder; ++k) {
      const ex total = expand(model.inertia[f] * acc[k] - rhs[k]);
      for (int j = -kMaxOrder; j <= kMaxOrder; ++j)
        res[f][k].push_back(reduce_trig(total.coeff(s.E, j), s));
    }
  }
  return res;
}

}  // namespace lrchain::derivation

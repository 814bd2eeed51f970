#include "lrchain/derivation/model.hpp"

namespace lrchain::derivation {

using namespace GiNaC;

symbol LatticeDescription::shift(std::size_t f, int m) const { return shifted.at(f).at(m + 3); }

void init_shift_symbols(LatticeDescription& model) {
  model.shifted.clear();
  for (const auto& name : model.fields) {
    std::vector<symbol> row;
    for (int m = -3; m <= 3; ++m) row.emplace_back(name + "[n" + (m < 0 ? "" : "+") + std::to_string(m) + "]");
    model.shifted.push_back(row);
  }
}

namespace {
// V'(r) truncated at quartic order of V (expv).
ex hertz_force_taylor(const Symbols& s, const ex& r) { return s.K2 * r + s.K3 * pow(r, 2) + s.K4 * pow(r, 3); }
}  // namespace

// (eq:Hertz): u'' = V'(u_{n+1}-u_n) - V'(u_n-u_{n-1}) - kappa(u_n - v_n),  rho v'' = kappa(u_n - v_n).
LatticeDescription resonant_chain_model(const Symbols& s) {
  LatticeDescription m;
  m.name = "resonant_chain";
  m.description = "locally resonant granular chain (eq:Hertz), fields u (beads) and v (resonators)";
  m.fields = {"u", "v"};
  m.inertia = {1, s.rho};
  m.parameters = {s.K2, s.K3, s.K4, s.kappa, s.rho};
  init_shift_symbols(m);
  const ex u_m = m.shift(0, -1), u0 = m.shift(0, 0), u_p = m.shift(0, 1), v0 = m.shift(1, 0);
  m.rhs = {hertz_force_taylor(s, u_p - u0) - hertz_force_taylor(s, u0 - u_m) - s.kappa * (u0 - v0),
           s.kappa * (u0 - v0)};
  // The paper's ubiquitous factor rho omega^2 - kappa (eq:gamma) as an input of the emitted code:
  // expanded polynomials in omega^2 lose digits to cancellation when rho omega^2 ~ kappa.
  m.emission_rewrites = {{pow(s.omega, 2), (s.mu + s.kappa) / s.rho}};
  m.emission_inputs = {{s.mu, "mu"}};
  return m;
}

// Homogeneous chain (Sec. 2, rho -> 0): u'' = V'(u_{n+1}-u_n) - V'(u_n-u_{n-1}).
LatticeDescription homogeneous_chain_model(const Symbols& s) {
  LatticeDescription m;
  m.name = "homogeneous_chain";
  m.description = "homogeneous precompressed granular chain (rho -> 0 limit, Chong13), field u";
  m.fields = {"u"};
  m.inertia = {1};
  m.parameters = {s.K2, s.K3, s.K4};
  init_shift_symbols(m);
  const ex u_m = m.shift(0, -1), u0 = m.shift(0, 0), u_p = m.shift(0, 1);
  m.rhs = {hertz_force_taylor(s, u_p - u0) - hertz_force_taylor(s, u0 - u_m)};
  return m;
}

}  // namespace lrchain::derivation

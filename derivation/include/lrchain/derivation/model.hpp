#pragma once
// A lattice model as data for the multiple-scale engine: fields, inertias and the
// right-hand sides of  inertia_f * d^2 field_f/dt^2 = rhs_f  written in shifted-field symbols.
#include <ginac/ginac.h>

#include <string>
#include <vector>

namespace lrchain::derivation {

// The symbols shared by every model (real parameters of the expansion).
struct Symbols {
  GiNaC::realsymbol K2{"K2"}, K3{"K3"}, K4{"K4"};  // Taylor coefficients of V (expv)
  GiNaC::realsymbol kappa{"kappa"}, rho{"rho"};   // resonator spring and mass ratio
  GiNaC::realsymbol omega{"omega"};               // carrier frequency
  GiNaC::realsymbol c{"c"};                       // group velocity (unknown until eps^2 E^1)
  GiNaC::realsymbol gamma{"gamma"};               // (eq:gamma), the NLS normalisation factor
  GiNaC::realsymbol mu{"mu"};                     // rho omega^2 - kappa (resonant chain, emission only)
  GiNaC::realsymbol D1{"D1"};                     // 4 sin^2(theta/2) = 2(1 - cos theta) (paper's D_1)
  GiNaC::realsymbol sigma{"sigma"};               // sin(theta) (paper's s = 2 i sigma)
  GiNaC::realsymbol eps{"eps"}, E{"E"};           // expansion parameter and carrier E = e^{i(n theta - omega t)}
};

struct LatticeDescription {
  std::string name;                 // identifier used for generated function names
  std::string description;          // one line for the report
  std::vector<std::string> fields;  // e.g. {"u", "v"}; field 0 carries the NLS amplitude A_{k,j}
  std::vector<GiNaC::ex> inertia;   // coefficient of d^2/dt^2 in each field's equation
  std::vector<GiNaC::ex> rhs;       // polynomial in shift(f, m) symbols and parameters
  std::vector<GiNaC::ex> parameters;     // the model's parameters other than theta and omega
  // Optional rewrites applied only to the emitted C++ (never to the derivation or its checks):
  // an intermediate computed without cancellation by the caller, e.g. mu = rho omega^2 - kappa with
  // omega^2 -> (mu + kappa)/rho. Each intermediate becomes an extra input of the evaluator.
  std::vector<std::pair<GiNaC::ex, GiNaC::ex>> emission_rewrites;   // pattern -> replacement
  std::vector<std::pair<GiNaC::ex, std::string>> emission_inputs;   // intermediate symbol -> name
  // Symbol standing for field f at site n+m inside rhs (m in [-3, 3]).
  GiNaC::symbol shift(std::size_t f, int m) const;
  std::vector<std::vector<GiNaC::symbol>> shifted;  // shifted[f][m+3]
};

// Creates the shift symbols for `fields` (call before writing rhs).
void init_shift_symbols(LatticeDescription& model);

// (eq:Hertz) with V'(r) = K2 r + K3 r^2 + K4 r^3 (expv): primary beads u with Hertz contacts and
// a linear resonator v of mass ratio rho attached by a spring kappa.
LatticeDescription resonant_chain_model(const Symbols& s);

// Homogeneous precompressed chain (no resonator, one field), the rho -> 0 limit (Chong13).
LatticeDescription homogeneous_chain_model(const Symbols& s);

}  // namespace lrchain::derivation

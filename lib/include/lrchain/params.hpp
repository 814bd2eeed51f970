#pragma once
// Model parameters of the locally resonant granular chain (Sec. 2, eq:Hertz, eq:Vr), and the valid
// range of every physical parameter lrchain takes (the one place: command-line options, TOML keys
// and the model file's [parameters] all use these).
#include <string>
#include <vector>

namespace lrchain {

// Dimensionless parameters: Hertz exponent alpha, precompression overlap delta0, resonator spring
// kappa, mass ratio rho = m2/m1; their ranges are the PhysicalRanges below.
struct Params {
  double alpha = 1.5;
  double delta0 = 4.0 / 9.0;
  double kappa = 1.0;
  double rho = 1.0 / 3.0;
};

// The paper's standard parameter set (alpha=3/2, delta0=4/9, kappa=1, rho=1/3).
inline Params paper_params() { return Params{}; }

// The valid interval of one physical parameter: (min, max], [min, max], ... and what it means.
struct PhysicalRange {
  const char* name;     // as the TOML key ("rho", "epsilon")
  double min, max;
  bool min_open, max_open;
  const char* meaning;  // one line: what the parameter is and why its bounds

  bool contains(double value) const;  // finite and inside the interval
  std::string interval() const;       // "(1, 5]"
};

// Hertz exponent: 3/2 for spheres, 2 for cones; contact laws of real bead shapes have 1 < alpha <= 5/2.
// The bound 5 keeps delta0^alpha and K2..K4 (expv) far inside double range for every delta0 below.
inline constexpr PhysicalRange alpha_range{
    "alpha", 1.0, 5.0, true, false, "Hertz exponent (3/2 for spheres, 2 for cones)"};
// Precompression overlap in units of the length scale R: Hertz's law holds for overlaps well below
// the bead radius (the paper uses 0.27 and 4/9; its maps over delta0 stop at 1).
inline constexpr PhysicalRange delta0_range{
    "delta0", 0.0, 10.0, true, false, "precompression overlap (in units of the length scale R)"};
// Resonator spring in units of the Hertz stiffness (the paper scales it to 1). Up to 1e4 the
// resonator frequency sqrt(kappa/rho) and the bead frequency sqrt(K2) differ by at most a factor
// 1e4 for the paper's rho, so a run's step count stays bounded.
inline constexpr PhysicalRange kappa_range{
    "kappa", 0.0, 1.0e4, true, false, "resonator spring constant (in units of the Hertz stiffness)"};
// Mass ratio m2/m1 (the paper: 0.1 to 17.8, its maps to 30): the acoustic band and the resonator
// frequency shrink like rho^(-1/2), so at 1e4 one period of the slow branch is already 100 times
// the bead's period.
inline constexpr PhysicalRange rho_range{"rho", 0.0, 1.0e4, true, false, "mass ratio m2/m1 of resonator to bead"};
// The small amplitude epsilon of the modulated wave (eq:cimi), the expansion parameter of the
// multiple-scale analysis: at most 1 (the paper uses 0.03). The meaning is shown to users as it is
// (error messages, docs/configs.md), so it cites the compiled paper's number, eq. (43).
inline constexpr PhysicalRange modulation_amplitude_range{
    "epsilon", 0.0, 1.0, true, false, "small amplitude of the modulated wave (eq. (43))"};

// The four model parameters' ranges, in the order alpha, delta0, kappa, rho.
const std::vector<PhysicalRange>& model_parameter_ranges();

// Throws InvalidParameter(range.name): "must be a finite number in (1, 5] (Hertz exponent ...); got X"
// unless range.contains(value). `name` overrides the parameter's name in the message (an option).
void check_in_range(double value, const PhysicalRange& range, const std::string& name = "");

// Throws InvalidParameter naming the first parameter outside its range and the range.
void validate(const Params& p);

// The largest drive amplitude at precompression delta0: the driver's stroke may not exceed the
// overlap (a larger one opens the first contact every period, outside the weakly nonlinear regime
// of Sec. 4.3). Throws InvalidParameter("amplitude") for amplitude outside (0, delta0].
void check_drive_amplitude(double amplitude, double delta0);

// Taylor coefficients of V (expv): V(r) = K2 r^2/2 + K3 r^3/3 + K4 r^4/4 + O(r^5).
struct TaylorCoefficients {
  double K2, K3, K4;
};
// K2 = alpha delta0^(alpha-1), K3 = -alpha(alpha-1) delta0^(alpha-2)/2,
// K4 = alpha(alpha-1)(alpha-2) delta0^(alpha-3)/6 (Sec. 2, below eq:expv).
TaylorCoefficients taylor_coefficients(const Params& p);

// Exact Hertzian force V'(r) = delta0^alpha - (delta0 - r)_+^alpha (derivative of eq:Vr).
double hertz_force(double r, double alpha, double delta0);

}  // namespace lrchain

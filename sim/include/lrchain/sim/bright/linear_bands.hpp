#pragma once
// The linear bands of a model lattice (the range of omega(theta), theta in [0, pi], of every branch)
// and the non-resonance condition of an exact bright breather: no harmonic k omega_b (k >= 1) may lie
// inside a band, or the breather radiates into it and no exact localized solution exists (Flach &
// Willis, Phys. Rep. 295, 181 (1998), Sec. 2). Bands are bounded, so only k <= max band / omega_b can
// resonate: every such k is checked, none is left out.
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "lrchain/index.hpp"
#include "lrchain/model.hpp"

namespace lrchain::sim::bright {

struct LinearBand {
  std::string branch;  // the model's branch name
  double lowest = 0;   // min over theta of omega(theta)
  double highest = 0;  // max over theta of omega(theta)
};

// Every branch's band from the model's dispersion relation (coefficients_at), sampled at `samples`
// wavenumbers in [0, pi] and its interior extrema refined by Brent's method (Boost.Math). A branch
// without a positive frequency at theta = 0 (acoustic) starts at 0.
std::vector<LinearBand> linear_bands(const Model& model, Index samples = 512);

struct Resonance {
  Index harmonic = 0;  // k of k omega_b (1: omega_b itself)
  LinearBand band;
};

// The lowest harmonic k omega_b, k = 1, 2, ..., inside a band (closed at the band's ends), or nullopt.
std::optional<Resonance> first_resonance(const std::vector<LinearBand>& bands, double omega_b);

// The interval (low, high) around omega_b in which no harmonic k omega_b (k >= 1) touches a band: where
// a continuation in omega_b from omega_b must stop (high = +inf when nothing bounds it). Precondition:
// first_resonance(bands, omega_b) is nullopt.
std::pair<double, double> non_resonant_window(const std::vector<LinearBand>& bands, double omega_b);

// InvalidParameter("omega_b", ...) naming the harmonic and the band when first_resonance finds one:
// "omega_b = 1.1 lies inside the band of branch u, [1, 1.183]" or "its harmonic 2 omega_b = 2.2 ...".
void check_non_resonance(const std::vector<LinearBand>& bands, double omega_b);

}  // namespace lrchain::sim::bright

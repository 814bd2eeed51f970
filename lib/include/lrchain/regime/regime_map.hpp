#pragma once
// Pixel maps of sign(omega'' h_tilde) (Sec. 3.3): the (theta, rho) plane of Fig. 2 and the
// (delta0, omega) band maps of Figs. 4-5. Evaluated in parallel with OpenMP.
#include <cstdint>
#include <vector>

#include "lrchain/dispersion.hpp"
#include "lrchain/params.hpp"
#include "lrchain/regime/grid_axis.hpp"

namespace lrchain::regime {

// Pixel value: outside the band (delta0-omega plane only), defocusing, focusing, singular.
enum PixelRegime : std::int8_t { outside = -1, defocusing = 0, focusing = 1, singular = 2 };

struct RegimeMap {
  Branch branch = Branch::optical;
  GridAxis x;  // rho (theta-rho plane) or delta0 (delta0-omega plane)
  GridAxis y;  // theta or omega
  std::vector<std::int8_t> values;  // values[j * x.n + i] at (x.at(i), y.at(j))

  std::int8_t at(Index i, Index j) const { return values[static_cast<std::size_t>(j * x.n + i)]; }
};

// sign(omega'' h_tilde) at (rho_i, theta_j); the other parameters from base (Fig. 2).
RegimeMap theta_rho_map(const Params& base, Branch b, const GridAxis& rho, const GridAxis& theta);

// sign(omega'' h_tilde) at (delta0_i, omega_j), theta from omega by theta_of_omega; pixels
// outside the band of branch b at delta0_i are `outside` (Figs. 4-5; the paper fixes kappa = 1).
RegimeMap delta0_omega_map(const Params& base, Branch b, const GridAxis& delta0,
                           const GridAxis& omega);

}  // namespace lrchain::regime

#pragma once
// Causes of a boundary between focusing and defocusing wavenumbers (Sec. 3.3, focdef):
// omega'' = 0, h_tilde = 0, a pole of h_tilde (eq:nonresonance1 / eq:nonresonance2), or the band edge.
#include <array>
#include <string_view>

namespace lrchain::regime {

enum class BoundaryCause { curvature_zero, h_tilde_zero, nonresonance1, nonresonance2, band_edge };

// The four smooth functions whose zeros can end a focusing interval, in a fixed order.
inline constexpr std::array<BoundaryCause, 4> kSmoothCauses{
    BoundaryCause::curvature_zero, BoundaryCause::h_tilde_zero, BoundaryCause::nonresonance1,
    BoundaryCause::nonresonance2};

std::string_view to_string(BoundaryCause c);
// Parses the names printed by to_string; throws InvalidParameter("cause", ...).
BoundaryCause parse_boundary_cause(std::string_view text);

}  // namespace lrchain::regime

#include "lrchain/regime/boundary_cause.hpp"

#include <string>

#include "lrchain/errors.hpp"

namespace lrchain::regime {

std::string_view to_string(BoundaryCause c) {
  switch (c) {
    case BoundaryCause::curvature_zero: return "curvature_zero";
    case BoundaryCause::h_tilde_zero: return "h_tilde_zero";
    case BoundaryCause::nonresonance1: return "nonresonance1";
    case BoundaryCause::nonresonance2: return "nonresonance2";
    case BoundaryCause::band_edge: return "band_edge";
  }
  return "band_edge";
}

BoundaryCause parse_boundary_cause(std::string_view text) {
  for (auto c : {BoundaryCause::curvature_zero, BoundaryCause::h_tilde_zero,
                 BoundaryCause::nonresonance1, BoundaryCause::nonresonance2,
                 BoundaryCause::band_edge})
    if (to_string(c) == text) return c;
  throw InvalidParameter("cause", "must be curvature_zero, h_tilde_zero, nonresonance1, "
                                  "nonresonance2 or band_edge, got '" + std::string(text) + "'");
}

}  // namespace lrchain::regime

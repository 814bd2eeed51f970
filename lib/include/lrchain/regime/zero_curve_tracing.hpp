#pragma once
// Zero sets of a smooth function in a rectangle of the plane traced as polylines by
// pseudo-arclength continuation: tangent predictor, corrector along the normal solved with
// TOMS 748, adaptive step. Seeds are zeros found on rows and columns of the rectangle.
#include <functional>
#include <vector>

#include "lrchain/index.hpp"

namespace lrchain::regime {

struct PlanePoint {
  double x = 0, y = 0;
};
using Polyline = std::vector<PlanePoint>;

struct PlaneBox {
  double x_lo = 0, x_hi = 1, y_lo = 0, y_hi = 1;
};

struct TraceOptions {
  double step = 4e-3;          // initial/maximal step in box-normalised units
  double min_step = 1e-7;      // give up a branch below this step
  double max_turn = 0.15;      // maximal tangent turn per step (radians)
  Index max_points = 20000;    // per polyline
  Index seed_lines = 48;       // rows and columns searched for seeds
  Index seed_samples = 513;    // samples per seed line
  double tolerance = 1e-12;    // corrector accuracy (normalised units)
};

// Traces every component of {F = 0} in box that a seed line crosses. Points are in (x, y).
std::vector<Polyline> trace_zero_set(const std::function<double(double, double)>& F,
                                     const PlaneBox& box, const TraceOptions& options = {});

}  // namespace lrchain::regime

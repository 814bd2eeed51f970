#include "lrchain/regime/grid_axis.hpp"

#include <string>

#include "lrchain/errors.hpp"

namespace lrchain::regime {

void validate(const GridAxis& axis, const char* name) {
  if (!(std::isfinite(axis.lo) && std::isfinite(axis.hi) && axis.lo < axis.hi))
    throw InvalidParameter(name, "range must be finite with lo < hi");
  if (axis.n < 2) throw InvalidParameter(name, "resolution must be >= 2 points");
  if (axis.logarithmic && !(axis.lo > 0.0))
    throw InvalidParameter(name, "logarithmic axis needs lo > 0");
}

}  // namespace lrchain::regime

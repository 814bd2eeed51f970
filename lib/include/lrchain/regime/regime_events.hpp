#pragma once
// Codimension-two points of the regime structure along a parameter line (Sec. 3.3): values of
// rho or delta0 where two boundary curves cross, where a pair of boundaries is born or dies
// (fold), or where a boundary enters through theta = pi; each located by TOMS 748 on a smooth
// event function, with the number of focusing intervals before and after.
#include <functional>
#include <string>
#include <vector>

#include "lrchain/regime/boundary_curves.hpp"
#include "lrchain/regime/focusing_intervals.hpp"
#include "lrchain/regime/grid_axis.hpp"

namespace lrchain::regime {

enum class EventKind { crossing, fold, band_edge_entry, unresolved };
std::string_view to_string(EventKind k);

struct RegimeEvent {
  double value = 0;  // parameter value (rho or delta0)
  double theta = 0;  // wavenumber where it happens
  EventKind kind = EventKind::unresolved;
  std::vector<BoundaryCause> causes;  // the boundary kinds involved
  Index intervals_before = 0;         // focusing intervals just below value
  Index intervals_after = 0;          // ... and just above
};

struct EventOptions {
  IntervalOptions intervals{1024, 1e-12};
  double value_tolerance = 1e-11;  // relative accuracy of event values
  Index max_depth = 40;            // subdivisions while isolating events
};

// All structure changes for the parameter on the scan grid (refined between grid points).
std::vector<RegimeEvent> regime_events(const Params& base, Branch b, ParameterAxis axis,
                                       const GridAxis& scan, const EventOptions& options = {});

// The regime functions at each value of a scanned parameter (called concurrently).
using RegimeFamily = std::function<RegimeFunctions(double value)>;

// The same for any family of regime functions (any model, any parameter).
std::vector<RegimeEvent> regime_events(const RegimeFamily& family, const GridAxis& scan,
                                       const EventOptions& options = {});

}  // namespace lrchain::regime

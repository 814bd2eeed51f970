#pragma once
// Focusing/defocusing regimes (sign of omega'' h_tilde, Sec. 3.3) of any loaded lattice model
// (docs/models.md): theta-intervals per branch, maps over (parameter, theta) for any named
// parameter, boundary curves and the structure changes along a parameter line. The resonant
// chain's Params functions in the other regime headers are this model's specialised path.
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "lrchain/model.hpp"
#include "lrchain/regime/boundary_curves.hpp"
#include "lrchain/regime/focusing_intervals.hpp"
#include "lrchain/regime/grid_axis.hpp"
#include "lrchain/regime/regime_events.hpp"
#include "lrchain/regime/regime_functions.hpp"

namespace lrchain::regime {

// theta -> the four smooth functions of `model` on `branch` (index into its branch names); all
// NaN where the branch has no real positive frequency (theta = 0 on an acoustic branch).
RegimeFunctions regime_functions(const Model& model, Index branch);

// Focusing theta-intervals in (0, pi] of one branch of a model.
std::vector<FocusingInterval> focusing_intervals(const Model& model, Index branch,
                                                 const IntervalOptions& options = {});

// A model with one named parameter varied and the others fixed: the evaluator inputs at any value.
class ParameterLine {
 public:
  static constexpr Index kMaxParameters = 64;
  // Throws InvalidParameter naming the model's parameters if `parameter` is not one of them.
  ParameterLine(const Model& base, std::string_view parameter);
  const ModelDefinition& definition() const { return base_.definition(); }
  const ModelParameter& parameter() const { return definition().parameters[index_]; }
  Index input_count() const { return static_cast<Index>(base_.inputs().size()); }
  // Evaluator inputs q (input_count() values: parameters, then intermediates) at parameter value x.
  // No range check; allocation-free. q.size() must be input_count().
  void inputs_at(double x, std::span<double> q) const;
  // Throws InvalidParameter(option, ...) unless both ends lie in the parameter's declared range.
  void check_range(double lo, double hi, const std::string& option) const;

 private:
  Model base_;
  Index index_ = 0;
};

// Pixel map of sign(omega'' h_tilde) over (parameter, theta) for one branch of a model; pixel
// values are those of regime_map.hpp (outside = no positive frequency on the branch there).
struct ModelRegimeMap {
  Index branch = 0;
  std::string parameter;
  GridAxis x;  // the parameter
  GridAxis y;  // theta
  std::vector<std::int8_t> values;  // values[j * x.n + i] at (x.at(i), y.at(j))

  std::int8_t at(Index i, Index j) const { return values[static_cast<std::size_t>(j * x.n + i)]; }
};

// The map at (x_i, theta_j); both ends of x inside the parameter's range, theta in [0, pi].
ModelRegimeMap parameter_theta_map(const Model& base, Index branch, std::string_view parameter,
                                   const GridAxis& x, const GridAxis& theta);

// Zero curves of the four smooth functions in the (parameter, theta) plane, parameter in [lo, hi].
std::vector<BoundaryCurve> boundary_curves(const Model& base, Index branch, std::string_view parameter,
                                           double lo, double hi, const TraceOptions& options = {});

// Every change of the boundary structure along the parameter on the scan grid (regime_events.hpp).
std::vector<RegimeEvent> regime_events(const Model& base, Index branch, std::string_view parameter,
                                       const GridAxis& scan, const EventOptions& options = {});

}  // namespace lrchain::regime

#pragma once
// Results of the dark-breather jobs as Python objects, shared by the resonant chain's jobs
// (dark_binding.cpp) and any model's (model_dark_binding.cpp).
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <functional>

#include "lrchain/sim/dark/continuation.hpp"
#include "lrchain/sim/dark/evolution.hpp"
#include "lrchain/sim/dark/floquet.hpp"
#include "lrchain/sim/dark/measures.hpp"
#include "lrchain/sim/dark/resonant_chain_shooting.hpp"

namespace lrchain::python {

// Newton's max|F| per iteration.
pybind11::array_t<double> residuals(const sim::dark::NewtonResult& r);
// {norm_squared, K_x, K_y, C_x, C_y, E_b, max_strain}.
pybind11::dict measures(const sim::dark::DarkMeasures& m);
// {multipliers (complex array), kind, max_modulus, ..., log_det}.
pybind11::dict floquet_dict(const sim::dark::FloquetResult& f);
// The per-period measures of an evolution: {period, t, E_b, C_x, K_x, position, depth, max_strain}.
pybind11::dict evolution_series(const sim::dark::DarkEvolution& e);

// A branch's points: {omega_b, tangent_omega, residual, iterations (int32), measures (a dict per point,
// by `measures_of`), floquet (a dict per point, or None without `floquet`), turning_points, stop_reason}.
pybind11::dict branch_arrays(const sim::dark::BranchResult& branch, bool floquet,
                             const std::function<pybind11::dict(const sim::dark::DarkMeasures&)>& measures_of);

}  // namespace lrchain::python

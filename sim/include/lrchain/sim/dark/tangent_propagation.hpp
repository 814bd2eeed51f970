#pragma once
// Variational equations of eq:Hertzd0S integrated on the recorded Runge-Kutta steps of an orbit
// (contact_integrator.hpp): Phi(t1) = dZ(t1)/dZ(t0) * Phi(t0) for many tangent columns, in blocks
// of columns processed in parallel (OpenMP), with Odeint's Runge-Kutta-Fehlberg 7(8) stepper.
#include <Eigen/Dense>
#include <atomic>

#include "lrchain/index.hpp"
#include "lrchain/sim/dark/contact_integrator.hpp"
#include "lrchain/sim/dark/strain_variational.hpp"

namespace lrchain::sim::dark {

// phi: 4N x m (column-major); each column is a tangent vector [dx dy dxdot dydot], overwritten.
// block: columns integrated together (row-major [4N][block] state; 8-16 keeps the stages in cache).
// Throws Interrupted once *stop is set (checked at every step of every block).
void propagate_tangents(const StrainLatticeOrbit& orbit, const OrbitRecord& record,
                        Eigen::MatrixXd& phi, Index block = 8, const std::atomic<bool>* stop = nullptr);

}  // namespace lrchain::sim::dark

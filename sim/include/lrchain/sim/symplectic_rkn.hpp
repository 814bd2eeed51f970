#pragma once
// High-order symplectic Runge-Kutta-Nystroem steppers for q'' = a(q) (the Hamiltonian lattices of
// eq:Hertz / eq:Hertzd0S), built on Boost.Odeint's symplectic_nystroem_stepper_base with published
// coefficients:
//  - S. Blanes and P. C. Moan, "Practical symplectic partitioned Runge-Kutta and
//    Runge-Kutta-Nystroem methods", J. Comput. Appl. Math. 142 (2002) 313-330, Table 3:
//    SRKN_11^b (order 6, symmetric "BAB", 11 force evaluations per step) and SRKN_14^a (order 6,
//    symmetric "ABA", 14 force evaluations per step);
//  - R. I. McLachlan, "On the numerical integration of ordinary differential equations by
//    symmetric composition methods", SIAM J. Sci. Comput. 16 (1995) 151-168: SS17, order 8, the
//    symmetric composition of 17 Stoermer-Verlet steps (17 force evaluations per step).
// The coefficients are checked by a unit test (orders 6 and 8 observed on a nonlinear oscillator).
//
// Odeint's stage l does q += a_l dt p, then p += b_l dt a(q). The paper's BAB method (kick first)
// therefore starts with a_0 = 0, and its ABA method ends with b_last = 0; in both cases one of the
// Odeint stages needs no new force evaluation (first-same-as-last, or a zero kick), which
// integrate_observed's force wrapper exploits (see StagedAcceleration in integrator.hpp).
#include <boost/array.hpp>
#include <boost/numeric/odeint/algebra/algebra_dispatcher.hpp>
#include <boost/numeric/odeint/algebra/operations_dispatcher.hpp>
#include <boost/numeric/odeint/stepper/base/symplectic_rkn_stepper_base.hpp>
#include <boost/numeric/odeint/util/resizer.hpp>

namespace lrchain::sim {

namespace rkn_coefficients {

// Blanes & Moan (2002) SRKN_11^b, order 6: kicks b_1..b_12, drifts a_1..a_11 (symmetric).
inline constexpr double bm11b_kick[12] = {
    0.041464998518262400, 0.19812867191806700,  -0.040006192104153300, 0.075253984301580700,
    -0.011511387420687900, 0.23666992478693110, 0.23666992478693110,   -0.011511387420687900,
    0.075253984301580700, -0.040006192104153300, 0.19812867191806700,  0.041464998518262400};
inline constexpr double bm11b_drift[11] = {
    0.12322977594627100, 0.29055379779955800,  -0.12704921262541700, -0.24633176106207500,
    0.35720887279592800, 0.2047770542914700,   0.35720887279592800,  -0.24633176106207500,
    -0.12704921262541700, 0.29055379779955800, 0.12322977594627100};

// Blanes & Moan (2002) SRKN_14^a, order 6: drifts a_1..a_15, kicks b_1..b_14 (symmetric).
inline constexpr double bm14a_drift[15] = {
    0.037859319840611600, 0.10263563310243500, -0.025867888266558700, 0.31424140307144700,
    -0.13014445951741500, 0.10641770036954300, -0.0087942431285105800, 0.2073050690568954,
    -0.0087942431285105800, 0.10641770036954300, -0.13014445951741500, 0.31424140307144700,
    -0.025867888266558700, 0.10263563310243500, 0.037859319840611600};
inline constexpr double bm14a_kick[14] = {
    0.091719152624461650, 0.18398317000500600, -0.056534365832888270, 0.0049146887747128540,
    0.14376112716835800,  0.32856769374680400, -0.19641146648645423,  -0.19641146648645423,
    0.32856769374680400,  0.14376112716835800, 0.0049146887747128540, -0.056534365832888270,
    0.18398317000500600,  0.091719152624461650};

// McLachlan (1995) SS17, order 8: Stoermer-Verlet weights w_1..w_9 (w_10..w_17 = w_8..w_1).
inline constexpr double ss17_weight[9] = {
    0.12886597938144329897, 0.5815140871052509624,  -0.41017537146985013753,
    0.1851469357165877327,  -0.40955234342085141934, 0.14440594108001204106,
    0.27833550039367965131, 0.31495668391629485789, -0.626994825405133975};

}  // namespace rkn_coefficients

namespace detail {

// Each method as Odeint stages {a_l}, {b_l} (stage l: q += a_l dt p, then p += b_l dt a(q)).

// Blanes-Moan SRKN_11^b (BAB): a = {0, a_1, ..., a_11}, b = {b_1, ..., b_12}.
struct BlanesMoan11b {
  static constexpr std::size_t stages = 12;
  static constexpr unsigned short order = 6;
  static boost::array<double, stages> drifts() {
    boost::array<double, stages> a{};
    for (std::size_t l = 1; l < stages; ++l) a[l] = rkn_coefficients::bm11b_drift[l - 1];
    return a;
  }
  static boost::array<double, stages> kicks() {
    boost::array<double, stages> b{};
    for (std::size_t l = 0; l < stages; ++l) b[l] = rkn_coefficients::bm11b_kick[l];
    return b;
  }
};

// Blanes-Moan SRKN_14^a (ABA): a = {a_1, ..., a_15}, b = {b_1, ..., b_14, 0}.
struct BlanesMoan14a {
  static constexpr std::size_t stages = 15;
  static constexpr unsigned short order = 6;
  static boost::array<double, stages> drifts() {
    boost::array<double, stages> a{};
    for (std::size_t l = 0; l < stages; ++l) a[l] = rkn_coefficients::bm14a_drift[l];
    return a;
  }
  static boost::array<double, stages> kicks() {
    boost::array<double, stages> b{};
    for (std::size_t l = 0; l + 1 < stages; ++l) b[l] = rkn_coefficients::bm14a_kick[l];
    return b;
  }
};

// McLachlan SS17: drift-kick-drift Stoermer-Verlet steps w_i dt with adjacent half drifts merged:
// a = {w_1/2, (w_1+w_2)/2, ..., (w_16+w_17)/2, w_17/2}, b = {w_1, ..., w_17, 0}.
struct McLachlanSS17 {
  static constexpr std::size_t stages = 18;
  static constexpr unsigned short order = 8;
  static double w(std::size_t i) {  // w_{i+1}, i = 0..16 (symmetric)
    return rkn_coefficients::ss17_weight[i < 9 ? i : 16 - i];
  }
  static boost::array<double, stages> drifts() {
    boost::array<double, stages> a{};
    a[0] = w(0) / 2;
    for (std::size_t l = 1; l < 17; ++l) a[l] = (w(l - 1) + w(l)) / 2;
    a[17] = w(16) / 2;
    return a;
  }
  static boost::array<double, stages> kicks() {
    boost::array<double, stages> b{};
    for (std::size_t l = 0; l < 17; ++l) b[l] = w(l);
    return b;
  }
};

}  // namespace detail

// An Odeint symplectic RKN stepper with the stage coefficients of `Method` (detail::*).
template <class Method, class Coor,
          class Algebra = typename boost::numeric::odeint::algebra_dispatcher<Coor>::algebra_type,
          class Operations = typename boost::numeric::odeint::operations_dispatcher<Coor>::operations_type>
class coefficient_rkn
    : public boost::numeric::odeint::symplectic_nystroem_stepper_base<
          Method::stages, Method::order, Coor, Coor, double, Coor, Coor, double, Algebra,
          Operations, boost::numeric::odeint::initially_resizer> {
  using base = boost::numeric::odeint::symplectic_nystroem_stepper_base<
      Method::stages, Method::order, Coor, Coor, double, Coor, Coor, double, Algebra, Operations,
      boost::numeric::odeint::initially_resizer>;

 public:
  coefficient_rkn() : base(Method::drifts(), Method::kicks()) {}
};

// Blanes-Moan SRKN_11^b: order 6, 12 Odeint stages, 11 distinct force evaluations per step.
template <class Coor, class... AlgebraOps>
using blanes_moan_srkn11b = coefficient_rkn<detail::BlanesMoan11b, Coor, AlgebraOps...>;
// Blanes-Moan SRKN_14^a: order 6, 15 Odeint stages (last kick 0), 14 force evaluations per step.
template <class Coor, class... AlgebraOps>
using blanes_moan_srkn14a = coefficient_rkn<detail::BlanesMoan14a, Coor, AlgebraOps...>;
// McLachlan SS17: order 8, 18 Odeint stages (last kick 0), 17 force evaluations per step.
template <class Coor, class... AlgebraOps>
using mclachlan_ss17 = coefficient_rkn<detail::McLachlanSS17, Coor, AlgebraOps...>;

}  // namespace lrchain::sim

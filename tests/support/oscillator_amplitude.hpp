#pragma once
// The amplitude, frequency and action of a single Duffing oscillator, independent of any lattice code.
#include <cmath>
#include <numbers>

#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <boost/math/tools/roots.hpp>

namespace lrchain::test {

// The amplitude A of the oscillator x'' + w0^2 x + b x^3 = 0 (x(0) = A, x'(0) = 0) whose period is
// 2 pi / omega: T(A) = 4 int_0^{pi/2} dphi / sqrt(w0^2 + b A^2 (1 + sin^2 phi) / 2) (energy
// conservation with x = A sin phi; Landau & Lifshitz, Mechanics, Sec. 11), by Gauss-Kronrod and TOMS 748.
inline double oscillator_amplitude(double w0, double b, double omega) {
  const auto period = [&](double A) {
    const auto integrand = [&](double phi) {
      return 1.0 / std::sqrt(w0 * w0 + 0.5 * b * A * A * (1.0 + std::sin(phi) * std::sin(phi)));
    };
    return 4.0 * boost::math::quadrature::gauss_kronrod<double, 31>::integrate(integrand, 0.0, std::numbers::pi / 2, 10, 1e-15);
  };
  boost::uintmax_t iterations = 100;
  // a soft oscillator (b < 0) oscillates below its separatrix, A < w0 / sqrt(-b), where T grows without bound
  const double highest = b < 0 ? (1 - 1e-9) * w0 / std::sqrt(-b) : 3.0;
  const auto root = boost::math::tools::toms748_solve([&](double A) { return period(A) - 2 * std::numbers::pi / omega; },
                                                      1e-3, highest, boost::math::tools::eps_tolerance<double>(50), iterations);
  return 0.5 * (root.first + root.second);
}

// The frequency 2 pi / T(A) of that oscillator at amplitude A (the period integral above).
inline double oscillator_frequency(double w0, double b, double A) {
  const auto integrand = [&](double phi) {
    return 1.0 / std::sqrt(w0 * w0 + 0.5 * b * A * A * (1.0 + std::sin(phi) * std::sin(phi)));
  };
  return 2 * std::numbers::pi /
         (4.0 * boost::math::quadrature::gauss_kronrod<double, 31>::integrate(integrand, 0.0, std::numbers::pi / 2, 10, 1e-15));
}

// Its action J(A) = (1/2 pi) oint p dx = (2/pi) int_0^{pi/2} A^2 cos^2 phi sqrt(w0^2 + b A^2 (1 + sin^2 phi)/2)
// dphi (x = A sin phi, as above).
inline double oscillator_action(double w0, double b, double A) {
  const auto integrand = [&](double phi) {
    const double c = std::cos(phi), s = std::sin(phi);
    return A * A * c * c * std::sqrt(w0 * w0 + 0.5 * b * A * A * (1.0 + s * s));
  };
  return 2 / std::numbers::pi *
         boost::math::quadrature::gauss_kronrod<double, 31>::integrate(integrand, 0.0, std::numbers::pi / 2, 10, 1e-15);
}

}  // namespace lrchain::test

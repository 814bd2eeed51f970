#pragma once
// The numerical check of the NLS coefficient h and of the group velocity c of any model, with no
// derivation in between: a plane wave of amplitude U on a periodic ring (theta = 2 pi k / N)
// oscillates at omega + h U^2 / 4 + O(U^4) (NLS i A_tau = h |A|^2 A for a uniform envelope with
// u_0 = eps (A E + c.c.), so U = 2 eps |A|; a ring carries no mean flow), and a small-amplitude
// Gaussian wave packet's centre moves at c.
#include <atomic>
#include <cstddef>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "lrchain/index.hpp"
#include "lrchain/model.hpp"
#include "lrchain/compiled_model_abi.h"
#include "lrchain/sim/model_lattice_bloch.hpp"
#include "lrchain/sim/run_record.hpp"

namespace lrchain::sim {

struct RingRunConfig {
  Index branch = 0;
  double theta = 0;                           // carrier wavenumber in (0, pi], a mode of the ring
  std::vector<double> amplitudes{0.02, 0.01};  // U: first-field amplitude of the plane wave
  Index sites = 0;                            // ring size N; 0: the smallest N >= 8 with theta N / (2 pi) whole
  double periods = 400;                       // carrier periods per frequency measurement
  double steps_per_period = 80;               // srkn11b steps per carrier period
  std::optional<double> packet_amplitude;     // default: a tenth of the smallest amplitude
  double packet_width = 24;                   // standard deviation of the packet's Gaussian envelope, in sites
  const std::atomic<bool>* stop = nullptr;    // set (SIGINT): lrchain::Interrupted at the next sample
  // Called after each plane wave and after the packet with the share of the run's lattice steps
  // (sites x steps) done, in [0, 1] (a front end's progress display; empty: none).
  std::function<void(double fraction)> progress;
};

// Throws InvalidParameter naming the option (theta, sites, amplitudes, periods, ...).
void validate(const RingRunConfig& c);
// The ring size the run uses (c.sites or the smallest ring >= 8 with theta on it).
Index ring_sites(const RingRunConfig& c);

// A plane wave counts as one while at least this fraction of its first field's energy
// sum_n (u_n^2 + u_n'^2 / omega^2) stays in the carrier mode theta; below it the wave broke up
// (modulational instability) and its frequency is not measurable.
inline constexpr double kPlaneWaveCarrierFraction = 0.9;
// The weakly nonlinear range of the ring check: |h| U^2 / 4 <= this fraction of omega (beyond it the
// O(U^4) terms of the frequency are not small and the comparison with omega + h U^2/4 says little).
inline constexpr double kWeaklyNonlinearShift = 0.02;
// |c| at or below this (times max(1, omega)) is a group velocity of zero (a band extremum, e.g. theta = pi).
inline constexpr double kZeroGroupVelocity = 1e-10;

// A plane wave on the ring, measured (measure_plane_wave).
struct PlaneWaveMeasurement {
  double frequency = 0;                 // least-squares slope of the carrier mode's phase
  double least_carrier_fraction = 1;    // smallest fraction of the first field's energy in the carrier mode
  std::optional<double> broke_up_at;    // first sample time with the fraction below kPlaneWaveCarrierFraction
};

struct RingAmplitude {
  double amplitude = 0;
  double measured_frequency = 0, predicted_frequency = 0;  // predicted: omega + h U^2 / 4
  double measured_shift = 0, predicted_shift = 0;           // frequency - omega
  std::optional<double> relative_disagreement;              // |measured - predicted shift| / |predicted|; none where h vanishes (|h| <= 1e-12 max(1, omega)) or the wave broke up
  double least_carrier_fraction = 1;                        // of the plane wave over the run (PlaneWaveMeasurement)
  std::optional<double> broke_up_at;                        // the plane wave broke up at this t: the frequency is not measurable
  bool weakly_nonlinear = true;                             // |h| U^2/4 <= kWeaklyNonlinearShift omega
};

struct RingRunResult {
  std::string model;
  double omega = 0, h = 0, group_velocity = 0;  // from the model's coefficient evaluators
  BlochMode mode;                               // from the lattice code (omega agrees to 1e-9)
  Index sites = 0, mode_number = 0;
  std::vector<RingAmplitude> amplitudes;
  Index packet_sites = 0;
  double packet_amplitude = 0, packet_width = 0, packet_duration = 0;
  double packet_speed = 0;                      // least-squares slope of the packet centre
  std::optional<double> packet_relative_disagreement;  // |speed - c| / |c|; none if |c| <= kZeroGroupVelocity max(1, omega)
  bool standing = false;                        // c counts as zero: the packet does not move (no relative disagreement)
  RunRecord record;                             // series: t, packet centre
  std::vector<std::string> warnings;            // each names the quantity (amplitude outside the weakly nonlinear range, ...)
  std::optional<std::string> failure;           // a measurement that is not one (a plane wave broke up): exit 3 with this reason
};

// Frequency of the plane wave U Re(K e^{i(n theta - omega t)}) on a periodic ring from the slope of
// the phase of the first field's mode amplitude sum_n u_0[n] e^{-i n theta} (sum_n (u_0[n] + i
// u_0'[n] / omega) e^{-i n theta} at theta = pi, where the first sum is real), least squares over
// `periods` carrier periods, and whether the wave stayed a plane wave (the fraction of the first
// field's energy in the carrier mode; the measurement stops where it broke up). `stop` set:
// lrchain::Interrupted at the next sample (8 per period).
PlaneWaveMeasurement measure_plane_wave(const lrchain_lattice_kernels& kernels, const std::vector<double>& parameters,
                                        const BlochMode& mode, Index sites, Index mode_number, double amplitude,
                                        double periods, double steps_per_period, const std::atomic<bool>* stop = nullptr);
// measure_plane_wave's frequency.
double measure_ring_frequency(const lrchain_lattice_kernels& kernels, const std::vector<double>& parameters,
                              const BlochMode& mode, Index sites, Index mode_number, double amplitude,
                              double periods, double steps_per_period, const std::atomic<bool>* stop = nullptr);

// Centre speed of a Gaussian packet U exp(-(n-n0)^2/(2 w^2)) Re(K e^{i(n theta - omega t)}) moving
// at c, from the centroid of sum_f m_f (u_f'^2 + omega^2 u_f^2) (the squared envelope); the
// centre track (t, X) goes to `track`. `stop` set: lrchain::Interrupted at the next sample.
double measure_packet_speed(const lrchain_lattice_kernels& kernels, const std::vector<double>& parameters,
                            const BlochMode& mode, double group_velocity, Index sites, Index mode_number,
                            double amplitude, double width, double duration, double steps_per_period,
                            TimeSeries& track, const std::atomic<bool>* stop = nullptr);

RingRunResult run_ring(const Model& model, const lrchain_lattice_kernels& kernels, const RingRunConfig& c);

}  // namespace lrchain::sim

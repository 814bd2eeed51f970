// The travelling wave job's checks (wave_job.hpp): every option, the branch and the linear wave at theta.
#include <cmath>
#include <filesystem>
#include <numbers>

#include <fmt/format.h>

#include "lrchain/errors.hpp"
#include "lrchain/jobs/wave_job.hpp"
#include "wave_standing.hpp"

namespace lrchain::jobs::wave {

namespace {

constexpr double kLargestAmplitude = 1000;  // an amplitude beyond any lattice's weakly or strongly nonlinear range

void check_range(const char* key, double value, double low, double high, bool open_low, bool open_high) {
  const bool ok = std::isfinite(value) && (open_low ? value > low : value >= low) && (open_high ? value < high : value <= high);
  if (!ok)
    throw InvalidParameter(key, fmt::format("{} is outside {}{}, {}{}", value, open_low ? "(" : "[", low, high,
                                            open_high ? ")" : "]"));
}

}  // namespace

void validate(const WaveConfig& c) {
  if (!c.model || !c.kernels) throw InvalidParameter("model", "the job needs a model and its lattice kernels");
  const Index branch = c.model->branch_or_only(c.branch);  // "is required" naming the branches of a model with several
  if (!std::isfinite(c.theta) || !(c.theta > -std::numbers::pi && c.theta <= std::numbers::pi))
    throw InvalidParameter("theta", fmt::format("{} is outside (-pi, pi]", c.theta));
  if (c.step == WaveStep::branch) {
    if (c.amplitudes.empty()) throw InvalidParameter("amplitudes", fmt::format("is required: increasing amplitudes in (0, {}]", kLargestAmplitude));
    for (std::size_t i = 0; i < c.amplitudes.size(); ++i)
      if (!std::isfinite(c.amplitudes[i]) || c.amplitudes[i] <= 0 || c.amplitudes[i] > kLargestAmplitude ||
          (i > 0 && c.amplitudes[i] <= c.amplitudes[i - 1]))
        throw InvalidParameter("amplitudes", fmt::format("must be increasing and in (0, {}] (entry {} is {})",
                                                         kLargestAmplitude, i + 1, c.amplitudes[i]));
  } else {
    check_range("amplitude", c.amplitude, 0, kLargestAmplitude, true, false);
    check_range("ramp", double(c.ramp), 1, 1000, false, false);
  }
  check_range("initial_harmonics", double(c.initial_harmonics), 2, 256, false, false);
  check_range("max_harmonics", double(c.max_harmonics), double(c.initial_harmonics), 256, false, false);
  check_range("tail_tolerance", c.tail_tolerance, 0, 1, true, true);
  check_range("tolerance", c.tolerance, 0, 1, true, true);
  check_range("max_iterations", double(c.max_iterations), 1, 1000, false, false);
  check_range("k_points", double(c.k_points), 1, 100000, false, false);
  check_range("unstable_tolerance", c.unstable_tolerance, 0, 1, true, true);
  if (c.step == WaveStep::fate) {
    check_range("ring_sites", double(c.ring_sites), 8, 100000, false, false);
    check_range("noise", c.noise, 0, 1, false, true);
    check_range("modulation", c.modulation, 0, 1, false, true);
    check_range("seed", double(c.seed), 1, 2147483647.0, false, false);
    if (c.periods != 0) check_range("periods", c.periods, 1, 1e6, false, false);
    check_range("steps_per_period", double(c.steps_per_period), 8, 10000, false, false);
    const double theta = ring_theta(c.theta, c.ring_sites);
    if (theta == 0 || std::abs(std::abs(theta) - std::numbers::pi) < 1e-12)
      throw InvalidParameter("theta", fmt::format("moves to {} on a ring of {} sites (ring_sites): a uniform or "
                                                  "standing wave, not a travelling one; give a theta inside (0, pi)",
                                                  theta, c.ring_sites));
    if (c.kernels->energy_density == nullptr)
      throw InvalidParameter("model", "the fate of a wave needs the lattice energy; this model's forces have none");
  }
  if (c.step == WaveStep::standing) check_standing(c);
  if (c.format != "csv" && c.format != "hdf5") throw InvalidParameter("format", "must be csv or hdf5");
  std::error_code ec;
  if (!c.out.empty() && std::filesystem::exists(c.out, ec) && !std::filesystem::is_directory(c.out, ec))
    throw InputError("--out '" + c.out + "' exists and is not a directory");
  sim::bloch_mode(*c.model, *c.kernels, branch, c.theta);  // InvalidParameter("theta") where there is no linear wave
}

}  // namespace lrchain::jobs::wave

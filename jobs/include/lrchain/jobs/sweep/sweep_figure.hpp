#pragma once
// The figure of a two-axis grid sweep: log10 of one scalar over the plane of the two axes (gnuplot,
// through lrchain::jobs::Figures: argv only, temporary name + rename), next to the results file.
// For a bright job over bright.theta, the ends of the focusing intervals of the base config's chain
// are drawn as vertical lines; when the second axis is bright.detuning, the exponent p of
// scalar ~ |detuning|^p fitted per theta (least squares in log-log) goes to a CSV and a figure.
#include <string>
#include <vector>

#include "lrchain/jobs/sweep/job.hpp"
#include "lrchain/jobs/sweep/results_file.hpp"
#include "lrchain/jobs/sweep/sweep_config.hpp"

namespace lrchain::jobs::sweep {

// The names of every file the sweep's figure writes into the output's directory (none without a
// figure).
std::vector<std::string> sweep_figure_files(const SweepConfig& c);

// Writes the data, scripts and PNGs (when gnuplot is installed) into the output's directory;
// returns the files written. InputError if the sweep is not a two-axis grid or `scalar` is unknown.
std::vector<std::string> write_sweep_figures(const SweepConfig& c, const Job& job, const SweepResults& r,
                                             const std::string& scalar);

// The figure of a one-axis "dark continue" sweep (figure = "stability"): every branch point in the
// (axis, omega_b) plane, coloured stable / real-unstable / oscillatory-unstable (oscillatory or
// period doubling, no real multiplier > 1), the weakly nonlinear part (before the first turning
// point) left of the axis value and the rest right of it, the first turning point and the band
// edge omega(pi) of each point. Returns the files written, as write_sweep_figures.
std::vector<std::string> write_stability_figure(const SweepConfig& c, const SweepResults& r);

// The figure the sweep file asks for (`figure`: a scalar's name, or "stability" for a "dark
// continue" sweep) from its complete results file, its files marked pending while they are written
// (side_files.hpp); returns the files written (none without a figure). `lrchain sweep` and
// lrchain.sweep() call it after a run that was not interrupted.
std::vector<std::string> write_requested_figure(const SweepConfig& c, const Job& job);

}  // namespace lrchain::jobs::sweep

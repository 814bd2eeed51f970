#pragma once
// The figure of a two-axis grid sweep: log10 of one scalar over the plane of the two axes (gnuplot,
// through lrchain::sim::Figures: argv only, temporary name + rename), next to the results file.
// For a bright job over bright.theta, the ends of the focusing intervals of the base config's chain
// are drawn as vertical lines; when the second axis is bright.detuning, the exponent p of
// scalar ~ |detuning|^p fitted per theta (least squares in log-log) goes to a CSV and a figure.
#include <string>
#include <vector>

#include "lrchain/sim/sweep/job.hpp"
#include "lrchain/sim/sweep/results_file.hpp"
#include "lrchain/sim/sweep/sweep_config.hpp"

namespace lrchain::sim::sweep {

// Writes the data, scripts and PNGs (when gnuplot is installed) into the output's directory;
// returns the files written. InputError if the sweep is not a two-axis grid or `scalar` is unknown.
std::vector<std::string> write_sweep_figures(const SweepConfig& c, const Job& job, const SweepResults& r,
                                             const std::string& scalar);

}  // namespace lrchain::sim::sweep

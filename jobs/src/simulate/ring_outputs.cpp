// JSON summary, data files and gnuplot figures of a ring run (ring_run.hpp).
#include <algorithm>

#include <fmt/format.h>

#include <nlohmann/json.hpp>

#include "lrchain/provenance_json.hpp"
#include "lrchain/jobs/output_files.hpp"
#include "ring_outputs.hpp"

namespace lrchain::jobs {

using namespace lrchain::sim;

namespace {
nlohmann::json optional_json(const std::optional<double>& v) { return v ? nlohmann::json(*v) : nlohmann::json(nullptr); }
}  // namespace

nlohmann::json to_json(const Model& model, const RingRunConfig& c, const RingRunResult& r) {
  nlohmann::json j;
  j["experiment"] = "ring";
  j["provenance"] = provenance_json();
  j["branch"] = model.definition().branch_names.at(c.branch);
  j["theta"] = c.theta;
  j["sites"] = r.sites;
  j["mode_number"] = r.mode_number;
  j["periods"] = c.periods;
  j["steps_per_period"] = c.steps_per_period;
  nlohmann::json kernel = nlohmann::json::array();
  for (const auto& k : r.mode.kernel) kernel.push_back({{"re", k.real()}, {"im", k.imag()}});
  j["prediction"] = {{"omega", r.omega}, {"h", r.h}, {"group_velocity", r.group_velocity},
                     {"kernel", kernel}, {"convention", "u_0 = U cos(n theta - omega t), frequency omega + h U^2/4"}};
  nlohmann::json rows = nlohmann::json::array();
  for (const auto& a : r.amplitudes) {
    const bool measured = !a.broke_up_at;  // a plane wave that broke up has no frequency
    nlohmann::json row = {{"amplitude", a.amplitude},
                          {"measured_frequency", measured ? nlohmann::json(a.measured_frequency) : nlohmann::json(nullptr)},
                          {"predicted_frequency", a.predicted_frequency},
                          {"measured_shift", measured ? nlohmann::json(a.measured_shift) : nlohmann::json(nullptr)},
                          {"predicted_shift", a.predicted_shift},
                          {"relative_disagreement", optional_json(a.relative_disagreement)},
                          {"least_carrier_fraction", a.least_carrier_fraction},
                          {"weakly_nonlinear", a.weakly_nonlinear}};
    if (!measured)
      row["not_measurable"] = fmt::format("the plane wave broke up at t = {:.6g}", *a.broke_up_at);
    rows.push_back(std::move(row));
  }
  j["amplitudes"] = rows;
  j["packet"] = {{"sites", r.packet_sites},
                 {"amplitude", r.packet_amplitude},
                 {"width", r.packet_width},
                 {"duration", r.packet_duration},
                 {"measured_speed", r.packet_speed},
                 {"group_velocity", r.group_velocity},
                 {"relative_disagreement", optional_json(r.packet_relative_disagreement)}};
  if (r.standing)
    j["packet"]["relative_disagreement_reason"] = fmt::format(
        "the group velocity {:.3g} counts as zero (|c| <= {:g} max(1, omega)): a standing wave, the packet does not move",
        r.group_velocity, kZeroGroupVelocity);
  j["warnings"] = r.warnings;
  j["failure"] = r.failure ? nlohmann::json(*r.failure) : nlohmann::json(nullptr);
  return j;
}

namespace {

double largest_amplitude(const RingRunResult& r) {
  double largest = 0;
  for (const auto& a : r.amplitudes) largest = std::max(largest, a.amplitude);
  return largest;
}

std::string frequency_script(const RingRunResult& r) {
  return fmt::format(R"GP(# Plane-wave frequency on the ring vs amplitude U: measured (points) and omega + h U^2/4 (line).
if (!exists("outfile")) outfile = 'frequency.png'
set terminal pngcairo size 900,650 font ",11"
set output outfile
set datafile separator ","
omega = {:.17g}
h = {:.17g}
set xlabel "plane-wave amplitude U of the first field (model units)"
set ylabel "frequency ω (model units)"
set key top left
set xrange [0:{:.17g}]
plot omega + h*x**2/4 with lines lw 2 lc rgb "blue" title "ω + h U^2/4 (derived)", \
     'ring_frequency.csv' using 1:2 skip 1 with points pt 7 ps 1.4 lc rgb "red" title "lattice"
)GP",
                     r.omega, r.h, 1.1 * largest_amplitude(r));
}

std::string packet_script(const RingRunResult& r) {
  return fmt::format(R"GP(# Centre of a small wave packet on the ring (lattice) vs a line of slope c (derived).
if (!exists("outfile")) outfile = 'packet.png'
set terminal pngcairo size 900,650 font ",11"
set output outfile
set datafile separator ","
c = {:.17g}
x0 = {:.17g}
set xlabel "t (model units)"
set ylabel "packet centre (site n)"
set key top left
plot 'series.csv' using 1:2 skip 1 with lines lw 2 lc rgb "red" title "lattice", \
     x0 + c*x with lines dt 2 lw 2 lc rgb "blue" title "n_0 + c t (derived)"
)GP",
                     r.group_velocity, double(r.packet_sites) / 2);
}

}  // namespace

std::vector<std::string> write_ring_outputs(const std::filesystem::path& dir, const RingRunResult& r,
                                            const nlohmann::json& summary, bool draw_figures) {
  ensure_directory(dir);
  TimeSeries frequencies;
  frequencies.names = {"amplitude", "measured_frequency", "predicted_frequency"};
  for (const auto& a : r.amplitudes)
    if (!a.broke_up_at)  // (a plane wave that broke up has no frequency)
      frequencies.data.insert(frequencies.data.end(), {a.amplitude, a.measured_frequency, a.predicted_frequency});
  write_csv(dir, "ring_frequency.csv", frequencies);
  return write_run_outputs(dir, r.record, summary.dump(2),
                           {{"frequency.gp", frequency_script(r), "frequency.png"},
                            {"packet.gp", packet_script(r), "packet.png"}},
                           draw_figures);
}

}  // namespace lrchain::jobs

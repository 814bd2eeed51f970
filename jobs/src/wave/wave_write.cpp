// write(WaveResult, out): profile.csv, branch.csv, growth.csv with growth.gp, summary.json, result.h5 (wave_job.hpp).
#include <cmath>
#include <numbers>
#include <sstream>
#include <string>
#include <utility>

#include <fmt/format.h>

#include "lrchain/jobs/output_lock.hpp"
#include "lrchain/jobs/wave_hdf5.hpp"
#include "lrchain/jobs/wave_job.hpp"
#include "lrchain/jobs/gnuplot_text.hpp"
#include "lrchain/jobs/output_files.hpp"
#include "lrchain/sim/wave/wave_nls.hpp"
#include "wave_standing.hpp"

namespace lrchain::jobs::wave {

using nlohmann::json;

namespace {

// profile.csv: xi and U_f(xi) of the last wave on its collocation phases.
void write_profile(const WaveResult& r, const std::string& dir) {
  const auto& w = r.waves.back();
  const Index points = 2 * w.harmonics + 1, fields = Index(r.mode.kernel.size());
  std::ostringstream os;
  os << "xi";
  for (Index f = 0; f < fields; ++f) os << ",u" << f;
  os << "\n";
  for (Index i = 0; i < points; ++i) {
    os << fmt::format("{:.17g}", 2 * std::numbers::pi * double(i) / double(points));
    for (Index f = 0; f < fields; ++f) os << fmt::format(",{:.17g}", w.profile(f * points + i));
    os << "\n";
  }
  jobs::write_file_atomic(dir, "profile.csv", os.str());
}

// branch.csv: one row per wave.
void write_branch(const WaveResult& r, const std::string& dir) {
  std::ostringstream os;
  os << "amplitude,omega,omega_shift,nls_omega_shift,harmonics,tail,residual\n";
  for (const auto& w : r.waves)
    os << fmt::format("{:.17g},{:.17g},{:.17g},{:.17g},{},{:.6g},{:.6g}\n", w.amplitude, w.omega, w.omega - w.omega_linear,
                      sim::wave::nls_frequency_shift(r.nls.h, w.amplitude), w.harmonics, w.tail, w.residual);
  jobs::write_file_atomic(dir, "branch.csv", os.str());
}

// growth.csv (K, exact and NLS growth rate) and growth.gp drawing both.
void write_growth(const WaveResult& r, const std::string& dir, jobs::Figures& figures) {
  const auto& s = *r.stability;
  std::ostringstream os;
  os << "K,growth_rate,nls_growth_rate\n";
  for (std::size_t i = 0; i < s.k.size(); ++i)
    os << fmt::format("{:.17g},{:.17g},{:.17g}\n", s.k[i], s.growth_rate[i],
                      sim::wave::nls_growth_rate(r.nls.curvature, r.nls.h_tilde, r.config.amplitude, s.k[i]));
  jobs::write_file_atomic(dir, "growth.csv", os.str());
  const auto literal = [](const std::string& text) { return jobs::gnuplot_text(text, jobs::GnuplotTextMode::enhanced); };
  figures.draw({"growth.gp",
                fmt::format("if (!exists(\"outfile\")) outfile = 'growth.png'\n"
                            "set terminal pngcairo size 1000,700\nset output outfile\n"
                            "set datafile separator ','\nset xlabel 'perturbation wavenumber K'\n"
                            "set ylabel 'growth rate max Re λ'\nset logscale x\nset key top left\n"
                            "set title '{} {} wave, θ = {:.6g}, A = {:.6g}: Floquet-Bloch growth rate and the NLS'\n"
                            "plot 'growth.csv' skip 1 u 1:2 w lp pt 7 ps 0.6 t 'exact wave', "
                            "'' skip 1 u 1:3 w l lw 2 dt 2 t 'NLS (h̃)'\n",
                            literal(r.config.model->name()), literal(r.branch), r.config.theta, r.config.amplitude),
                "growth.png"});
}

// fate.csv (per carrier period: t, deviation, participation, entropy, dark and bright structures), fate_stages.csv
// (the dark and bright stages: from, until, count, width, depth; empty fields when none), fate_energy.csv (e_n at
// the end) and fate.gp drawing the three against t with the thresholds of the classification.
void write_fate(const WaveResult& r, const std::string& dir, jobs::Figures& figures) {
  const auto& f = *r.fate;
  std::ostringstream os;
  os << "t,deviation,participation,entropy,dark_structures,bright_structures\n";
  for (std::size_t i = 0; i < f.t.size(); ++i)
    os << fmt::format("{:.17g},{:.17g},{:.17g},{:.17g},{},{}\n", f.t[i], f.deviation[i], f.participation[i], f.entropy[i],
                      f.dark[i], f.bright[i]);
  jobs::write_file_atomic(dir, "fate.csv", os.str());
  const auto field = [](double x) { return std::isfinite(x) ? fmt::format("{:.17g}", x) : std::string(); };
  std::ostringstream st;
  st << "structures,from,until,count,width,depth\n";
  for (const auto& [name, stage] : {std::pair{"dark", f.dark_stage}, std::pair{"bright", f.bright_stage}})
    st << fmt::format("{},{},{},{},{},{}\n", name, field(stage.from), field(stage.until),
                      stage.found() ? std::to_string(stage.count) : std::string(), field(stage.width), field(stage.depth));
  jobs::write_file_atomic(dir, "fate_stages.csv", st.str());
  std::ostringstream e;
  e << "n,energy_density\n";
  for (std::size_t n = 0; n < f.energy_density.size(); ++n) e << fmt::format("{},{:.17g}\n", n, f.energy_density[n]);
  jobs::write_file_atomic(dir, "fate_energy.csv", e.str());
  const auto literal = [](const std::string& text) { return jobs::gnuplot_text(text, jobs::GnuplotTextMode::enhanced); };
  figures.draw({"fate.gp",
                fmt::format("if (!exists(\"outfile\")) outfile = 'fate.png'\n"
                            "set terminal pngcairo size 1000,900\nset output outfile\nset datafile separator ','\n"
                            "set multiplot layout 2,1 title '{} {} wave, θ = {:.6g}, A = {:.6g} on {} sites: {}'\n"
                            "set xlabel 'time'\nset ylabel '{}'\nset logscale y\nset key top left\n"
                            "plot 'fate.csv' skip 1 u 1:2 w l lw 2 t 'deviation from the exact wave', {} w l dt 2 t "
                            "'broken ({})'\n"
                            "unset logscale y\nset ylabel 'participation P, entropy S'\nset yrange [0:1.05]\n"
                            "plot 'fate.csv' skip 1 u 1:3 w l lw 2 t 'energy participation P', "
                            "'' skip 1 u 1:4 w l lw 2 t 'spectral entropy S', {} w l dt 2 t 'localized below ({})', "
                            "{} w l dt 3 t 'disordered above ({})', "
                            "'' skip 1 u 1:($5 / 10) w steps lc rgb '#606060' t 'dark structures / 10'\nunset multiplot\n",
                            literal(r.config.model->name()), literal(r.branch), r.theta, r.config.amplitude,
                            r.config.ring_sites, sim::wave::to_string(f.fate),
                            // the deviation's measure (wave_fate.hpp): strains of a translation-invariant model
                            f.strain_deviation ? "max_n |Δu_n - ΔU_n| / (2 A sin(θ/2))" : "max_n |u_n - U_n| / A",
                            sim::wave::kBrokenDeviation,
                            sim::wave::kBrokenDeviation, sim::wave::kLocalizedParticipation,
                            sim::wave::kLocalizedParticipation, sim::wave::kDisorderedEntropy,
                            sim::wave::kDisorderedEntropy),
                "fate.png"});
}

}  // namespace

json write(const WaveResult& r, const std::filesystem::path& out) {
  json j = to_json(r);
  const json summary = j;  // result.h5's: the summary without the figures
  const std::string dir = out.string();
  const OutputLock lock(dir);
  const jobs::OutputListing earlier = jobs::list_output_files(dir);
  jobs::Figures figures(dir);
  if (!r.waves.empty()) {
    write_profile(r, dir);
    write_branch(r, dir);
  }
  if (r.stability) write_growth(r, dir, figures);
  if (r.fate) write_fate(r, dir, figures);
  if (!r.standing.empty()) write_standing(r, dir, figures);
  figures.finish(j);
  if (r.config.format == "hdf5") write_wave_hdf5(out / "result.h5", summary);
  jobs::write_file_atomic(dir, "summary.json", j.dump(2) + "\n");
  jobs::record_stale_files(out, earlier, j);
  return j;
}

}  // namespace lrchain::jobs::wave

// The standing wave step of the wave job (wave_standing.hpp).
#include "wave_standing.hpp"

#include <cmath>
#include <numeric>
#include <numbers>
#include <sstream>

#include <fmt/format.h>

#include "lrchain/errors.hpp"
#include "lrchain/jobs/gnuplot_text.hpp"

namespace lrchain::jobs::wave {

using nlohmann::json;

namespace {

// theta = 2 pi j / ring_sites: j.
Index ring_index(const WaveConfig& c) {
  return Index(std::llround(c.theta * double(c.ring_sites) / (2 * std::numbers::pi)));
}

// One spatial period of the standing wave: q = ring_sites / gcd(j, ring_sites) sites.
Index period_sites(const WaveConfig& c) { return c.ring_sites / std::gcd(ring_index(c), c.ring_sites); }

sim::CompiledLattice ring_of(const WaveConfig& c, Index sites) {
  return sim::CompiledLattice(*c.kernels, sim::lattice_parameters(*c.model), sites, true, sim::LatticeForm::displacement);
}

}  // namespace

std::vector<double> ramp_amplitudes(const WaveConfig& c) {
  std::vector<double> amplitudes;
  for (Index i = 1; i <= c.ramp; ++i) amplitudes.push_back(c.amplitude * double(i) / double(c.ramp));
  return amplitudes;
}

void check_standing(const WaveConfig& c) {
  if (!std::isfinite(double(c.ring_sites)) || c.ring_sites < 8 || c.ring_sites > 100000)
    throw InvalidParameter("ring_sites", fmt::format("{} is outside [8, 100000]", c.ring_sites));
  const Index j = ring_index(c);
  if (j <= 0 || 2 * j >= c.ring_sites)
    throw InvalidParameter("theta", fmt::format("moves to {} on a ring of {} sites (ring_sites): a standing wave needs "
                                                "0 < theta < pi (at 0 and pi the two counter-propagating waves are one "
                                                "wave: `lrchain wave solve`)",
                                                ring_theta(c.theta, c.ring_sites), c.ring_sites));
  const Index branch = c.model->branch_or_only(c.branch);
  if (sim::bloch_mode(*c.model, *c.kernels, branch, ring_theta(c.theta, c.ring_sites)).kernel.empty())
    throw InvalidParameter("theta", "the first field is at rest in this branch's mode there: no standing wave of amplitude A");
  if (!sim::wave::reflection_symmetry(ring_of(c, std::max<Index>(period_sites(c), 5))))
    throw InvalidParameter("model", fmt::format("{} is not reflection symmetric (no u_f[n] -> +-u_f[d_f - n] maps its "
                                                "lattice onto itself): it has no standing waves",
                                                c.model->name()));
}

void run_standing(const WaveConfig& c, WaveResult& r) {
  sim::CompiledLattice period = ring_of(c, period_sites(c));
  r.reflection = sim::wave::reflection_symmetry(ring_of(c, std::max<Index>(period_sites(c), 5)));
  sim::wave::StandingWaveBranch b = sim::wave::continue_standing_wave(
      period, r.mode, r.theta, ramp_amplitudes(c), solver_options<sim::wave::StandingWaveOptions>(c));
  r.standing = std::move(b.waves);
  r.failure = b.stopped;
  r.failed_at = b.stopped_at;
  if (r.failure) return;
  sim::CompiledLattice ring = ring_of(c, c.ring_sites);
  r.standing_floquet = sim::wave::standing_floquet(ring, r.standing.back());
}

json standing_json(const WaveResult& r) {
  const WaveConfig& c = r.config;
  json j;
  j["ring_sites"] = c.ring_sites;
  j["period_sites"] = period_sites(c);
  j["ring_theta"] = r.theta;
  j["reflection"] = r.reflection ? json{{"sign", r.reflection->sign}, {"offsets", r.reflection->offsets}} : json(nullptr);
  json waves = json::array();
  for (const auto& w : r.standing)
    waves.push_back({{"amplitude", w.amplitude},
                     {"omega", w.omega},
                     {"omega_shift", w.omega - w.omega_linear},
                     {"harmonics", w.harmonics},
                     {"tail", w.tail},
                     {"residual", w.residual},
                     {"newton_steps", w.newton_steps},
                     {"least_contact_overlap", w.least_contact_overlap ? json(*w.least_contact_overlap) : json(nullptr)}});
  j["waves"] = waves;
  j["omega"] = r.standing.empty() || r.failure ? json(nullptr) : json(r.standing.back().omega);
  json coefficients = json::array();  // c_{f,n,k}: [field][site][k]
  if (!r.standing.empty() && !r.failure) {
    const auto& w = r.standing.back();
    const Index fields = w.coefficients.rows() / w.sites;
    for (Index f = 0; f < fields; ++f) {
      json sites = json::array();
      for (Index n = 0; n < w.sites; ++n) {
        const Eigen::VectorXd row = w.coefficients.row(f * w.sites + n).transpose();
        sites.push_back(std::vector<double>(row.data(), row.data() + row.size()));
      }
      coefficients.push_back(sites);
    }
  }
  j["coefficients"] = coefficients;
  if (r.standing_floquet) {
    const auto& f = *r.standing_floquet;
    std::vector<double> re, im;
    for (const auto& mu : f.multipliers) {
      re.push_back(mu.real());
      im.push_back(mu.imag());
    }
    j["floquet"] = {{"stable", f.stable}, {"largest_modulus", f.largest_modulus}, {"re", re}, {"im", im}};
  } else {
    j["floquet"] = nullptr;
  }
  return j;
}

std::array<Eigen::VectorXd, 2> standing_profiles(const sim::wave::StandingWave& w) {
  std::array<Eigen::VectorXd, 2> at;
  sim::wave::standing_positions(w, w.sites, 0.0, at[0]);
  sim::wave::standing_positions(w, w.sites, std::numbers::pi / (2 * w.omega), at[1]);
  return at;
}

void write_standing(const WaveResult& r, const std::string& dir, Figures& figures) {
  std::ostringstream os;
  os << "amplitude,omega,omega_shift,harmonics,tail,residual\n";
  for (const auto& w : r.standing)
    os << fmt::format("{:.17g},{:.17g},{:.17g},{},{:.6g},{:.6g}\n", w.amplitude, w.omega, w.omega - w.omega_linear,
                      w.harmonics, w.tail, w.residual);
  write_file_atomic(dir, "standing.csv", os.str());
  if (r.failure) return;
  const auto& w = r.standing.back();
  const Index fields = w.coefficients.rows() / w.sites;
  const auto [at0, at_quarter] = standing_profiles(w);
  std::ostringstream p;
  p << "n";
  for (Index f = 0; f < fields; ++f) p << ",u" << f << "_t0,u" << f << "_quarter_period";
  p << "\n";
  for (Index n = 0; n < w.sites; ++n) {
    p << n;
    for (Index f = 0; f < fields; ++f) p << fmt::format(",{:.17g},{:.17g}", at0(f * w.sites + n), at_quarter(f * w.sites + n));
    p << "\n";
  }
  write_file_atomic(dir, "standing_profile.csv", p.str());
  if (!r.standing_floquet) return;
  std::ostringstream fl;
  fl << "re,im,modulus\n";
  for (const auto& mu : r.standing_floquet->multipliers)
    fl << fmt::format("{:.17g},{:.17g},{:.17g}\n", mu.real(), mu.imag(), std::abs(mu));
  write_file_atomic(dir, "floquet.csv", fl.str());
  const auto literal = [](const std::string& text) { return gnuplot_text(text, GnuplotTextMode::enhanced); };
  figures.draw({"floquet.gp",
                fmt::format("if (!exists(\"outfile\")) outfile = 'floquet.png'\n"
                            "set terminal pngcairo size 800,800\nset output outfile\nset datafile separator ','\n"
                            "set size square\nset xlabel 'Re μ'\nset ylabel 'Im μ'\nset parametric\nset trange [0:2*pi]\n"
                            "set title '{} {} standing wave, θ = {:.6g}, A = {:.6g}: Floquet multipliers on {} sites'\n"
                            "plot cos(t), sin(t) w l lc rgb 'gray' t 'unit circle', "
                            "'floquet.csv' skip 1 u 1:2 w p pt 7 ps 0.8 t 'multipliers'\n",
                            literal(r.config.model->name()), literal(r.branch), r.theta, r.config.amplitude,
                            r.config.ring_sites),
                "floquet.png"});
}

}  // namespace lrchain::jobs::wave

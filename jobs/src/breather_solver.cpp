// The dense or matrix-free path of the exact-breather jobs (breather_solver.hpp).
#include "lrchain/jobs/breather_solver.hpp"

#include <chrono>
#include <cmath>
#include <string>

#include "lrchain/errors.hpp"
#include "lrchain/sim/dark/shooting.hpp"

namespace lrchain::jobs {

void validate(const BreatherSolverOptions& o) {
  if (o.solver != "auto" && o.solver != "dense" && o.solver != "krylov")
    throw InvalidParameter("solver", "must be auto, dense or krylov, got '" + o.solver + "'");
  if (o.krylov_sites < 9) throw InvalidParameter("krylov_sites", "must be an integer >= 9");
  if (o.krylov_band < 1) throw InvalidParameter("krylov_band", "must be an integer >= 1");
  if (o.floquet_count < 1) throw InvalidParameter("floquet_count", "must be an integer >= 1");
  if (o.dark_floquet != "auto" && o.dark_floquet != "window" && o.dark_floquet != "arnoldi")
    throw InvalidParameter("dark_floquet", "must be auto, window or arnoldi, got '" + o.dark_floquet + "'");
}

bool use_krylov(const BreatherSolverOptions& o, Index sites) {
  return o.solver == "krylov" || (o.solver == "auto" && sites > o.krylov_sites);
}

bool use_dark_window(const BreatherSolverOptions& o, Index sites) {
  return o.dark_floquet == "window" || (o.dark_floquet == "auto" && sites > o.krylov_sites);
}

namespace {

nlohmann::json complex_json(std::complex<double> l) {
  return {{"re", l.real()}, {"im", l.imag()}, {"modulus", std::abs(l)}};
}

// The windowed multipliers: certified ones with their value, the others null with the reason.
nlohmann::json to_json(const sim::bright::WindowedFloquet& w, double seconds) {
  nlohmann::json j;
  j["method"] = "core window, dense monodromy; residual on the full lattice";
  j["center"] = w.center;
  j["window_sites"] = w.sites;
  j["check_window_sites"] = w.check_sites;
  j["sites"] = w.full_sites;
  nlohmann::json values = nlohmann::json::array();
  for (const auto& m : w.localized) {
    nlohmann::json v = m.certified ? complex_json(m.lambda)
                                   : nlohmann::json{{"re", nullptr}, {"im", nullptr}, {"modulus", nullptr}};
    v["window_value"] = complex_json(m.lambda);
    v["window_difference"] = m.window_difference;
    v["residual"] = m.residual ? nlohmann::json(*m.residual) : nlohmann::json(nullptr);
    v["certified"] = m.certified;
    v["reason"] = m.certified ? nlohmann::json(nullptr) : nlohmann::json(m.reason);
    values.push_back(v);
  }
  j["multipliers"] = values;
  j["localized_found"] = w.localized_found;
  nlohmann::json trivial = nlohmann::json::array();
  for (const auto& l : w.trivial) trivial.push_back(complex_json(l));
  j["trivial"] = trivial;
  j["max_extended_modulus"] = w.max_extended_modulus;
  j["extended"] = "the phonon band of the linear lattice at rest: on the unit circle";
  if (w.verdict) {
    j["stable"] = w.verdict->kind() == "stable";
    j["kind"] = w.verdict->kind();
    j["reason"] = nullptr;
  } else {
    j["stable"] = nullptr;
    j["kind"] = nullptr;
    j["reason"] = w.verdict_reason;
  }
  j["products"] = w.products;
  j["window_seconds"] = w.window_seconds;
  j["certify_seconds"] = w.certify_seconds;
  j["seconds"] = seconds;
  return j;
}

// The dark window's record and the background's Floquet-Bloch spectrum.
nlohmann::json to_json(const sim::dark::WindowedDarkFloquet& w, double seconds) {
  nlohmann::json j = to_json(w.window, seconds);
  j["method"] = "dip window solved by Newton, dense monodromy; residual on the full lattice; the background's "
                "Floquet-Bloch multipliers for the continuous spectrum";
  j["extended"] = "the window's modes of the background; the continuous spectrum is the background's (below)";
  j["window_newton_iterations"] = w.window_newton_iterations;
  j["window_newton_residual"] = std::isfinite(w.window_newton_residual) ? nlohmann::json(w.window_newton_residual)
                                                                        : nlohmann::json(nullptr);
  const sim::dark::BackgroundSpectrum& b = w.background;
  nlohmann::json bj;
  const bool known = b.reason.empty();
  bj["ring_sites"] = b.ring_sites;
  bj["wavenumbers"] = known ? nlohmann::json(b.wavenumbers) : nlohmann::json(nullptr);
  bj["amplitude"] = b.amplitude;
  bj["newton_residual"] = b.newton_residual;
  bj["truncation"] = b.truncation;
  bj["max_modulus"] = known ? nlohmann::json(b.max_modulus) : nlohmann::json(nullptr);
  bj["max_wavenumber"] = known ? nlohmann::json(b.max_wavenumber) : nlohmann::json(nullptr);
  bj["ring_leading"] = known ? complex_json(b.ring_leading) : nlohmann::json(nullptr);
  bj["ring_residual"] = known ? nlohmann::json(b.ring_residual) : nlohmann::json(nullptr);
  bj["on_unit_circle"] = known ? nlohmann::json(!b.unstable) : nlohmann::json(nullptr);
  bj["kind"] = known ? nlohmann::json(b.unstable ? b.unstable->kind() : "stable") : nlohmann::json(nullptr);
  bj["reason"] = known ? nlohmann::json(nullptr) : nlohmann::json(b.reason);
  bj["seconds"] = w.background_seconds;
  j["background"] = bj;
  j["scope"] = "an instability is certified on this lattice (a localized eigenvector's residual) or on the infinite "
               "one (the background's continuous spectrum); stable: the localized multipliers certified and the "
               "continuous spectrum on the unit circle, the infinite lattice's spectrum (a finite ring's extended "
               "modes may still grow, by O(1/N))";
  return j;
}

}  // namespace

nlohmann::json to_json(const KrylovRecord& r) {
  nlohmann::json j;
  j["gmres_iterations"] = r.newton.gmres_iterations;
  j["jacobian_products"] = r.newton.jacobian_products;
  j["preconditioner_builds"] = r.newton.preconditioner_builds;
  j["probe_columns"] = r.newton.probe_columns;
  j["solve_seconds"] = r.solve_seconds;
  if (r.floquet) {
    nlohmann::json f;
    nlohmann::json values = nlohmann::json::array();
    for (const auto& l : r.floquet->multipliers) values.push_back(complex_json(l));
    f["multipliers"] = values;
    f["requested"] = r.floquet->requested;
    f["converged"] = r.floquet->converged;
    f["restarts"] = r.floquet->restarts;
    f["products"] = r.floquet->products;
    f["seconds"] = r.floquet_seconds;
    j["leading_floquet"] = f;
  }
  if (r.windowed) j["windowed_floquet"] = to_json(*r.windowed, r.floquet_seconds);
  if (r.dark_windowed) j["windowed_floquet"] = to_json(*r.dark_windowed, r.floquet_seconds);
  return j;
}

sim::dark::NewtonResult solve_breather(const sim::dark::DarkShooting& shooting, Eigen::VectorXd q0, double omega_b,
                                       const sim::dark::NewtonOptions& newton, const BreatherSolverOptions& o,
                                       std::optional<KrylovRecord>& record) {
  if (!use_krylov(o, shooting.sites())) return sim::dark::newton_solve(shooting, std::move(q0), omega_b, newton);
  const auto start = std::chrono::steady_clock::now();
  record.emplace();
  sim::dark::NewtonKrylovOptions k;
  k.newton = newton;
  k.band = o.krylov_band;
  sim::dark::NewtonResult r = sim::dark::newton_krylov_solve(shooting, std::move(q0), omega_b, k, &record->newton);
  record->solve_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return r;
}

void krylov_floquet(const sim::dark::DarkShooting& shooting, const Eigen::VectorXd& z0, double omega_b,
                    const BreatherSolverOptions& o, KrylovRecord& record) {
  const auto start = std::chrono::steady_clock::now();
  sim::dark::KrylovFloquetOptions f;
  f.count = o.floquet_count;
  record.floquet = sim::dark::leading_multipliers(shooting, z0, omega_b, f);
  record.floquet_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void windowed_floquet(const sim::dark::DarkShooting& shooting, const sim::bright::WindowLattice& lattice,
                      const Eigen::VectorXd& z0, double omega_b, const BreatherSolverOptions& o, double unit_tolerance,
                      KrylovRecord& record) {
  const auto start = std::chrono::steady_clock::now();
  sim::bright::WindowedFloquetOptions w;
  w.count = o.floquet_count;
  w.unit_tolerance = unit_tolerance;
  record.windowed = sim::bright::windowed_floquet(shooting, lattice, z0, omega_b, w);
  record.floquet_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void windowed_dark_floquet(const sim::dark::DarkShooting& shooting, const sim::bright::WindowLattice& lattice,
                           const Eigen::VectorXd& z0, double omega_b, const BreatherSolverOptions& o,
                           double newton_tolerance, KrylovRecord& record) {
  const auto start = std::chrono::steady_clock::now();
  sim::dark::WindowedDarkFloquetOptions w;
  w.window.count = o.floquet_count;
  w.newton.tolerance = newton_tolerance;
  record.dark_windowed = sim::dark::windowed_dark_floquet(shooting, lattice, z0, omega_b, w);
  record.floquet_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace lrchain::jobs

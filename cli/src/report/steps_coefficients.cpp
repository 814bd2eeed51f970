// Reproduce step: the frequencies, periods and group velocities the paper quotes (Secs. 4-5),
// from the coefficient library (generated from the GiNaC derivation), and the analogues of
// Fig. 1 (dispersion branches) and Fig. 3 (c, omega'', h_tilde versus theta).
#include <algorithm>
#include <boost/math/tools/roots.hpp>
#include <cmath>
#include <fmt/format.h>
#include <numbers>
#include <nlohmann/json.hpp>
#include <sstream>
#include <tuple>
#include <vector>

#include "lrchain/ansatz/bright_breather.hpp"
#include "lrchain/coefficients.hpp"
#include "lrchain/dispersion.hpp"
#include "lrchain/jobs/output_files.hpp"
#include "steps.hpp"

namespace lrchain::report {

namespace {

constexpr double pi = std::numbers::pi;

// theta in (0, pi) with omega_+(theta) = omega (the optical branch increases on (0, pi]).
double optical_theta_of_omega(const Params& p, double omega) {
  auto f = [&](double th) { return dispersion_omega(p, Branch::optical, th) - omega; };
  std::uintmax_t iters = 200;
  const auto r = boost::math::tools::toms748_solve(
      f, 1e-9, pi, boost::math::tools::eps_tolerance<double>(50), iters);
  return 0.5 * (r.first + r.second);
}

// ||x(0)||_inf of the bright-breather ansatz (eq:focus_app) on a long lattice.
double ansatz_strain_sup(const BrightBreatherAnsatz& a, long N) {
  std::vector<double> x(2 * N + 1), y(2 * N + 1);
  a.strains(-N, 0.0, x, y);
  double m = 0;
  for (double v : x) m = std::max(m, std::abs(v));
  return m;
}

// theta/pi of the coefficient figures: 600 uniform samples, plus samples closing in on each pole
// of h_tilde (a sign change between samples that are not both near 0, located as a zero of
// 1/h_tilde by TOMS 748), so that the curve leaves the frame at a pole instead of ending at the
// last uniform sample (rho = 10 near theta/pi = 0.117 is narrower than the sampling).
std::vector<double> figure_thetas_over_pi(const Params& p) {
  std::vector<double> t;
  for (int i = 1; i <= 600; ++i) t.push_back(i / 600.0);
  std::vector<double> near_poles;
  for (const Branch b : {Branch::optical, Branch::acoustic}) {
    const auto h = [&](double x) { return coefficients(p, b, pi * x).h_tilde; };
    for (std::size_t i = 1; i < t.size(); ++i) {
      const double left = h(t[i - 1]), right = h(t[i]);
      if (!std::isfinite(left) || !std::isfinite(right) || left * right >= 0 ||
          std::min(std::abs(left), std::abs(right)) <= 0.1)
        continue;
      // 1/h_tilde is 0 where the coefficient is singular (not finite): that is the pole.
      const auto inverse = [&](double x) {
        const double v = h(std::clamp(x, t[i - 1], t[i]));
        return std::isfinite(v) ? 1.0 / v : 0.0;
      };
      std::uintmax_t iterations = 100;
      const auto bracket = boost::math::tools::toms748_solve(inverse, t[i - 1], t[i],
                                                             boost::math::tools::eps_tolerance<double>(45), iterations);
      const double pole = 0.5 * (bracket.first + bracket.second);
      if (!std::isfinite(pole)) continue;
      for (const double distance : {3e-4, 1e-4, 3e-5, 1e-5, 3e-6, 1e-6})
        for (const double x : {pole - distance, pole + distance})
          if (x > t[i - 1] && x < t[i]) near_poles.push_back(x);
    }
  }
  t.insert(t.end(), near_poles.begin(), near_poles.end());
  std::sort(t.begin(), t.end());
  return t;
}

void write_figures(const std::filesystem::path& dir, Section& s) {
  jobs::ensure_directory(dir);
  // Fig. 1: the two branches at rho = 1/3; Fig. 3: c, omega'', h_tilde for rho = 1/3 and 10.
  for (double rho : {1.0 / 3.0, 10.0}) {
    std::ostringstream csv;
    csv << "theta_over_pi,omega_opt,omega_ac,c_opt,c_ac,curv_opt,curv_ac,htilde_opt,htilde_ac\n";
    const Params p = paper_chain(rho);
    for (const double theta_over_pi : figure_thetas_over_pi(p)) {
      const double th = pi * theta_over_pi;
      const auto o = coefficients(p, Branch::optical, th);
      const auto a = coefficients(p, Branch::acoustic, th);
      auto v = [](double d) { return std::isfinite(d) ? fmt::format("{:.10g}", d) : std::string("NaN"); };
      csv << fmt::format("{:.9g},{},{},{},{},{},{},{},{}\n", th / pi, v(o.omega), v(a.omega),
                         v(o.group_velocity), v(a.group_velocity), v(o.curvature), v(a.curvature),
                         v(o.h_tilde), v(a.h_tilde));
    }
    const std::string tag = rho < 1 ? "rho_1_3" : "rho_10";
    jobs::write_file_atomic(dir, "coefficients_" + tag + ".csv", csv.str());
  }
  jobs::Figures figures(dir);
  figures.draw({"dispersion.gp",
                      "if (!exists(\"outfile\")) outfile = 'dispersion.png'\n"
                      "set terminal pngcairo size 700,500 font 'DejaVu Sans,11' noenhanced\n"
                      "set output outfile\nset datafile separator ','\n"
                      "set xlabel 'wavenumber θ/π'\nset ylabel 'frequency ω (dimensionless)'\nset key bottom right\n"
                      "set title 'Dispersion relation, eq. (7): ρ = 1/3, δ0 = 4/9, κ = 1'\n"
                      "plot 'coefficients_rho_1_3.csv' u 1:2 w l lw 2 t 'optical ω₊', "
                      "'' u 1:3 w l lw 2 dt 2 t 'acoustic ω₋'\n",
                      "dispersion.png"});
  std::string gp =
      "if (!exists(\"outfile\")) outfile = 'coefficients.png'\n"
      "set terminal pngcairo size 1100,500 font 'DejaVu Sans,10' noenhanced\n"
      "set output outfile\nset datafile separator ','\nset multiplot layout 1,2\n"
      "set xlabel 'wavenumber θ/π'\nset ylabel 'c, d²ω/dθ², h̃ (dimensionless)'\nset yrange [-3:3]\n"
      "set key font ',9'\nset grid\n"
      // h̃ has poles (breakdown of the non-resonance conditions; the CSV samples close in on
      // each): the first sample past a pole, where h̃ changes sign between values not both near 0,
      // is left out of the line, which breaks it there instead of joining +inf to -inf; the line
      // leaves the frame on both sides. The CSV keeps every value.
      "pole(v, p) = v * p < 0 && (abs(v) < abs(p) ? abs(v) : abs(p)) > 0.1\n"
      "h8(v) = (p8 = last8, last8 = v, pole(v, p8) ? NaN : v)\n"
      "h9(v) = (p9 = last9, last9 = v, pole(v, p9) ? NaN : v)\n";
  // The key where the curves leave room: bottom left at rho = 1/3, bottom right at rho = 10 (whose
  // h̃ pole sits near theta = 0.11 pi).
  for (const auto& [tag, label, corner] : {std::tuple{"rho_1_3", "ρ = 1/3", "left"}, std::tuple{"rho_10", "ρ = 10", "right"}}) {
    gp += fmt::format(
        "set key bottom {}\n"
        "set title \"c (green), d²ω/dθ² (red), h̃ (blue): {}; optical solid, acoustic dashed\"\n"
        "last8 = NaN; last9 = NaN\n"
        "plot '{f}' u 1:4 w l lc rgb '#1a9850' lw 2 t 'c₊', '{f}' u 1:5 w l lc rgb '#1a9850' dt 2 lw 2 t 'c₋', "
        "'{f}' u 1:6 w l lc rgb '#d73027' lw 2 t 'd²ω₊/dθ²', '{f}' u 1:7 w l lc rgb '#d73027' dt 2 lw 2 t 'd²ω₋/dθ²', "
        "'{f}' u 1:(h8($8)) w l lc rgb '#4575b4' lw 2 t 'h̃₊', '{f}' u 1:(h9($9)) w l lc rgb '#4575b4' dt 2 lw 2 t 'h̃₋'\n",
        corner, label, fmt::arg("f", std::string("coefficients_") + tag + ".csv"));
  }
  gp += "unset multiplot\n";
  figures.draw({"coefficients.gp", gp, "coefficients.png"});
  nlohmann::json listed;  // the report lists missing figures itself; this prints the warning line
  figures.finish(listed);
  s.figures.push_back({"coefficients/dispersion.png", "fig:w_vs_q",
                       "Optical (solid) and acoustic (dashed) branches of eq:disp1d on [0, pi], "
                       "rho = 1/3, delta0 = 4/9, kappa = 1."});
  s.figures.push_back({"coefficients/coefficients.png", "fig:disp",
                       "Group velocity c, curvature omega'' and h_tilde versus theta/pi for rho = 1/3 "
                       "(left) and rho = 10 (right), optical solid, acoustic dashed; h_tilde clipped "
                       "to [-3, 3] near its poles (breakdown of eq:nonresonance1 and eq:nonresonance2)."});
  s.links = {"coefficients/coefficients_rho_1_3.csv", "coefficients/coefficients_rho_10.csv"};
}

Section coefficients_section(const StepContext& ctx) {
  Section s;
  s.id = "coefficients";
  s.title = "Frequencies, periods and group velocities (Secs. 2-5)";
  s.intro = "From the coefficient library, whose NLS coefficients are generated by the GiNaC "
            "derivation (lrchain-derive). omega_b = omega + sign(h_tilde) 1e-4 as in Sec. 4.1; "
            "T_b = 2 pi / omega_b.";
  const Params p = paper_chain(1.0 / 3.0);
  const double half = 5e-5;
  s.rows.push_back(equals_row("omega_opt = omega_+(pi), rho = 1/3", "Sec. 5.3", "2.4495", 2.4495,
                              dispersion_omega(p, Branch::optical, pi), half));
  s.rows.push_back(equals_row("omega_acs = omega_-(pi), rho = 1/3", "Sec. 5.3", "1.4142", 1.4142,
                              dispersion_omega(p, Branch::acoustic, pi), half));
  s.rows.push_back(equals_row("omega_opt = omega_+(pi), rho = 1", "Secs. 5.3, 5.4", "2.2882", 2.2882,
                              dispersion_omega(paper_chain(1.0), Branch::optical, pi), half));
  s.rows.push_back(erratum(equals_row("omega_opt = omega_+(pi), rho = 1 (caption)", "Fig. 19 caption", "2.2282",
                                      2.2282, dispersion_omega(paper_chain(1.0), Branch::optical, pi), half,
                                      "the text of Secs. 5.3-5.4 prints 2.2882"),
                           "Fig. 19 caption"));

  const BrightBreatherAnsatz pi2(p, Branch::optical, pi / 2);
  s.rows.push_back(equals_row("omega_b = omega_+(pi/2) - 1e-4", "Fig. 6 caption", "2.1752", 2.1752,
                              pi2.omega_b(), half));
  s.rows.push_back(equals_row("T_b at theta = pi/2", "Sec. 4.2", "2.8885", 2.8885, pi2.period(), half));
  s.rows.push_back(equals_row("50.125 T_b (snapshot time)", "Fig. 6 caption", "~ 145", 145,
                              50.125 * pi2.period(), 0.5));
  s.rows.push_back(equals_row("200 T_b", "Fig. 6 caption", "~ 578", 578, 200 * pi2.period(), 0.5));
  s.rows.push_back(equals_row("c_+(pi/2)", "Sec. 4.2", "~ 0.23", 0.23, pi2.group_velocity(), 0.005));

  const BrightBreatherAnsatz pi8(p, Branch::optical, pi / 8);
  s.rows.push_back(equals_row("omega_+(pi/8)", "Sec. 4.2", "2.0098", 2.0098, pi8.omega(), half));
  s.rows.push_back(equals_row("omega_b at theta = pi/8", "Sec. 4.2", "2.0097", 2.0097, pi8.omega_b(), half));
  s.rows.push_back(equals_row("T_b at theta = pi/8", "Sec. 4.2", "3.1265", 3.1265, pi8.period(), half));
  s.rows.push_back(unresolved(equals_row("||x_n(0)||_inf at theta = pi/8 (eq:focus_app)", "Sec. 4.2", "~ 0.208",
                                         0.208, ansatz_strain_sup(pi8, 2000), 5e-4, "ansatz on n = -2000..2000"),
                              "Amplitude"));

  const BrightBreatherAnsatz t35(p, Branch::optical, 3 * pi / 5);
  s.rows.push_back(equals_row("theta = 3 pi/5", "Sec. 4.2", "~ 1.885", 1.885, 3 * pi / 5, 5e-4));
  s.rows.push_back(equals_row("omega_b at theta = 3 pi/5", "Fig. 10 caption", "2.2512", 2.2512, t35.omega_b(), half));
  s.rows.push_back(equals_row("T_b at theta = 3 pi/5", "Sec. 4.2", "2.791", 2.791, t35.period(), 5e-4));
  s.rows.push_back(equals_row("200 T_b at theta = 3 pi/5", "Sec. 4.2", "~ 558.2", 558.2, 200 * t35.period(), 0.05));

  const BrightBreatherAnsatz a17845(p, Branch::acoustic, 1.7845);
  s.rows.push_back(equals_row("T_b, acoustic theta = 1.7845", "Sec. 4.2", "5.187", 5.187, a17845.period(), 5e-4));
  const BrightBreatherAnsatz a1948(p, Branch::acoustic, 1.948);
  s.rows.push_back(equals_row("omega_b, acoustic theta = 1.948", "Fig. 11 caption", "1.264", 1.264, a1948.omega_b(), 5e-4));
  s.rows.push_back(equals_row("200 T_b, acoustic theta = 1.948", "Fig. 11 caption", "~ 994", 994, 200 * a1948.period(), 0.5));
  const BrightBreatherAnsatz a187(p, Branch::acoustic, 1.87);
  s.rows.push_back(equals_row("omega_b, acoustic theta = 1.87", "Fig. 12 caption", "1.2402", 1.2402, a187.omega_b(), half));
  s.rows.push_back(equals_row("700 T_b, acoustic theta = 1.87", "Fig. 12 caption", "3546.44", 3546.44, 700 * a187.period(), 0.005));

  const Params p10 = paper_chain(10.0);
  const BrightBreatherAnsatz r10(p10, Branch::optical, 1.23);
  s.rows.push_back(equals_row("omega_b, rho = 10, theta = 1.23", "Fig. 13 caption", "1.5414", 1.5414, r10.omega_b(), half));
  s.rows.push_back(equals_row("200 T_b, rho = 10, theta = 1.23", "Fig. 13 caption", "~ 815.28", 815.28, 200 * r10.period(), 0.005));
  s.rows.push_back(equals_row("c_+(1.23), rho = 10", "Sec. 4.3", "~ 0.6", 0.6, r10.group_velocity(), 0.05));
  s.rows.push_back(equals_row("c_-(1.23), rho = 10", "Sec. 4.3", "~ 0.0754", 0.0754,
                              coefficients(p10, Branch::acoustic, 1.23).group_velocity, 5e-5));

  const double theta_drive = optical_theta_of_omega(p10, 2.1);
  s.rows.push_back(equals_row("theta with omega_+(theta) = 2.1, rho = 10", "Sec. 4.3", "~ 2.34", 2.34, theta_drive, 0.005));
  s.rows.push_back(equals_row("T_0 = 2 pi / omega_0", "Sec. 4.3", "~ 2.99", 2.99, 2 * pi / 2.1, 0.005));
  s.rows.push_back(equals_row("A_0 / delta0", "Sec. 4.3", "0.135", 0.135, 0.06 / (4.0 / 9.0), 5e-4));

  const Params p7 = paper_chain(0.32, 0.27);
  const double theta0 = 252 * pi / 401;
  s.rows.push_back(equals_row("theta_0 = 252 pi / 401", "Sec. 5.1", "~ 1.97", 1.97, theta0, 0.005));
  s.rows.push_back(equals_row("omega_-(theta_0), rho = 0.32, delta0 = 0.27", "Sec. 5.1", "~ 1.17", 1.17,
                              dispersion_omega(p7, Branch::acoustic, theta0), 0.005));
  s.rows.push_back(equals_row("omega_-'(theta_0) (dark-breather speed)", "Sec. 5.1", "c_db ~ 0.3", 0.3,
                              coefficients(p7, Branch::acoustic, theta0).group_velocity, 0.05));
  s.rows.push_back(equals_row("second harmonic 2 pi - 2 theta_0", "Sec. 5.1", "~ 2.3", 2.3, 2 * pi - 2 * theta0, 0.05));
  s.rows.push_back(equals_row("c_-(2.003), rho = 0.32, delta0 = 0.27", "Sec. 5.1", "~ 0.29", 0.29,
                              coefficients(p7, Branch::acoustic, 2.003).group_velocity, 0.005));
  write_figures(ctx.out / "coefficients", s);
  return s;
}

}  // namespace

std::vector<Step> coefficient_steps() {
  return {{"coefficients", "Frequencies, periods and group velocities", 1, coefficients_section}};
}

}  // namespace lrchain::report

#include "lrchain/regime/zero_curve_tracing.hpp"

#include <algorithm>
#include <cmath>

#include "lrchain/regime/zero_finding.hpp"

namespace lrchain::regime {

namespace {

struct Vec {
  double u, v;
};

// F in box-normalised coordinates (u, v) in [0, 1]^2.
struct Normalised {
  const std::function<double(double, double)>& F;
  PlaneBox box;
  double operator()(Vec p) const {
    return F(box.x_lo + p.u * (box.x_hi - box.x_lo), box.y_lo + p.v * (box.y_hi - box.y_lo));
  }
  PlanePoint to_plane(Vec p) const {
    return {box.x_lo + p.u * (box.x_hi - box.x_lo), box.y_lo + p.v * (box.y_hi - box.y_lo)};
  }
};

// Unit gradient by central differences; {0,0} if it vanishes.
Vec unit_gradient(const Normalised& G, Vec p) {
  const double h = 1e-6;
  const double gu = (G({p.u + h, p.v}) - G({p.u - h, p.v})) / (2 * h);
  const double gv = (G({p.u, p.v + h}) - G({p.u, p.v - h})) / (2 * h);
  const double n = std::hypot(gu, gv);
  if (!(n > 0.0) || !std::isfinite(n)) return {0.0, 0.0};
  return {gu / n, gv / n};
}

bool inside(Vec p) { return p.u >= 0.0 && p.u <= 1.0 && p.v >= 0.0 && p.v <= 1.0; }

struct TracedBranch {
  std::vector<Vec> points;
  bool closed = false;
};

// Continuation of {G = 0} from the zero `start` along `dir` * tangent until it leaves the box,
// closes on itself, or the step collapses.
TracedBranch continue_branch(const Normalised& G, Vec start, double dir, const TraceOptions& o) {
  TracedBranch out;
  Vec p = start;
  Vec n = unit_gradient(G, p);
  Vec t{-n.v * dir, n.u * dir};
  if (n.u == 0.0 && n.v == 0.0) return out;
  double h = o.step;
  double travelled = 0.0;
  while (static_cast<int>(out.points.size()) < o.max_points) {
    const Vec q{p.u + h * t.u, p.v + h * t.v};  // predictor along the tangent
    const Vec nq = unit_gradient(G, q);
    if (nq.u == 0.0 && nq.v == 0.0) break;
    // Corrector: the zero of G on the normal segment q + s nq, |s| <= h (TOMS 748).
    const auto g = [&](double s) { return G({q.u + s * nq.u, q.v + s * nq.v}); };
    const double ga = g(-h), gb = g(h);
    if (!(std::isfinite(ga) && std::isfinite(gb)) || (ga < 0.0) == (gb < 0.0)) {
      h *= 0.5;
      if (h < o.min_step) break;
      continue;
    }
    const double s = solve_bracketed(g, -h, h, ga, gb, o.tolerance);
    const Vec r{q.u + s * nq.u, q.v + s * nq.v};
    const Vec nr = unit_gradient(G, r);
    Vec tr{-nr.v, nr.u};
    if (tr.u * t.u + tr.v * t.v < 0.0) tr = {-tr.u, -tr.v};
    const double cos_turn = std::clamp(tr.u * t.u + tr.v * t.v, -1.0, 1.0);
    const double advance = (r.u - p.u) * t.u + (r.v - p.v) * t.v;
    if (std::acos(cos_turn) > o.max_turn || advance <= 0.0) {
      h *= 0.5;
      if (h < o.min_step) break;
      continue;
    }
    out.points.push_back(r);
    travelled += std::hypot(r.u - p.u, r.v - p.v);
    if (!inside(r)) break;
    if (travelled > 4 * o.step && std::hypot(r.u - start.u, r.v - start.v) < 1.5 * h) {
      out.points.push_back(start);
      out.closed = true;
      break;
    }
    p = r;
    t = tr;
    if (std::acos(cos_turn) < o.max_turn / 3) h = std::min(o.step, 1.5 * h);
  }
  return out;
}

double distance_to(const std::vector<Vec>& curve, Vec p) {
  double best = 1e300;
  for (const Vec& c : curve) best = std::min(best, std::hypot(c.u - p.u, c.v - p.v));
  return best;
}

}  // namespace

std::vector<Polyline> trace_zero_set(const std::function<double(double, double)>& F,
                                     const PlaneBox& box, const TraceOptions& o) {
  const Normalised G{F, box};
  ZeroFindingOptions zf{o.seed_samples, o.tolerance};
  // Seeds: zeros on rows (fixed u) and columns (fixed v) strictly inside the box.
  std::vector<Vec> seeds;
  for (int k = 0; k < o.seed_lines; ++k) {
    const double c = (k + 0.5) / o.seed_lines;
    for (double v : find_zeros([&](double v) { return G({c, v}); }, 0.0, 1.0, zf))
      seeds.push_back({c, v});
    for (double u : find_zeros([&](double u) { return G({u, c}); }, 0.0, 1.0, zf))
      seeds.push_back({u, c});
  }
  std::vector<std::vector<Vec>> curves;
  for (const Vec& s : seeds) {
    bool covered = false;
    for (const auto& c : curves)
      if (distance_to(c, s) < 2.0 * o.step) {
        covered = true;
        break;
      }
    if (covered) continue;
    TracedBranch fwd = continue_branch(G, s, +1.0, o);
    std::vector<Vec> curve;
    if (!fwd.closed) {
      TracedBranch bwd = continue_branch(G, s, -1.0, o);
      curve.assign(bwd.points.rbegin(), bwd.points.rend());
    }
    curve.push_back(s);
    curve.insert(curve.end(), fwd.points.begin(), fwd.points.end());
    curves.push_back(std::move(curve));
  }
  std::vector<Polyline> out;
  out.reserve(curves.size());
  for (const auto& c : curves) {
    Polyline line;
    line.reserve(c.size());
    for (const Vec& p : c) line.push_back(G.to_plane(p));
    out.push_back(std::move(line));
  }
  return out;
}

}  // namespace lrchain::regime

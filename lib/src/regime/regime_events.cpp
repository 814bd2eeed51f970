#include "lrchain/regime/regime_events.hpp"

#include <algorithm>
#include <boost/math/tools/minima.hpp>
#include <cmath>
#include <functional>
#include <limits>
#include <numbers>
#include <optional>

#include "lrchain/errors.hpp"
#include "lrchain/regime/zero_finding.hpp"

namespace lrchain::regime {

std::string_view to_string(EventKind k) {
  switch (k) {
    case EventKind::crossing: return "crossing";
    case EventKind::fold: return "fold";
    case EventKind::band_edge_entry: return "band_edge_entry";
    case EventKind::unresolved: return "unresolved";
  }
  return "unresolved";
}

namespace {

constexpr double kPi = std::numbers::pi;

bool same_sequence(const RegimeStructure& a, const RegimeStructure& b) {
  if (a.roots.size() != b.roots.size()) return false;
  for (std::size_t i = 0; i < a.roots.size(); ++i)
    if (a.roots[i].cause != b.roots[i].cause) return false;
  return true;
}

int count(const RegimeStructure& s, BoundaryCause c) {
  return static_cast<int>(std::count_if(s.roots.begin(), s.roots.end(),
                                        [c](const BoundaryRoot& r) { return r.cause == c; }));
}

// theta of the index-th zero of cause c, or NaN if there are not that many.
double nth_root(const RegimeStructure& s, BoundaryCause c, int index) {
  for (const auto& r : s.roots)
    if (r.cause == c && index-- == 0) return r.theta;
  return std::numeric_limits<double>::quiet_NaN();
}

// A smooth scalar function of the parameter whose zero is the event, with its kind, causes and
// theta at the solution.
struct EventFunction {
  EventKind kind;
  std::vector<BoundaryCause> causes;
  std::function<double(double)> g;
  std::function<double(double)> theta_at;
};

class EventFinder {
 public:
  EventFinder(const RegimeFamily& family, const EventOptions& o) : family_(family), o_(o) {}

  RegimeFunctions functions(double value) const { return family_(value); }
  RegimeStructure structure(double value) const {
    return regime_structure(functions(value), o_.intervals);
  }

  // Classifies the change between two neighbouring structures as one simple event.
  std::optional<EventFunction> classify(const RegimeStructure& lo, const RegimeStructure& hi) const {
    std::vector<BoundaryCause> changed;
    std::vector<int> diff;
    for (BoundaryCause c : kSmoothCauses) {
      const int d = count(hi, c) - count(lo, c);
      if (d != 0) {
        changed.push_back(c);
        diff.push_back(d);
      }
    }
    if (changed.empty()) return crossing(lo, hi);
    if (changed.size() == 1 && std::abs(diff[0]) == 2) return fold(lo, hi, changed[0]);
    return edge_entry(changed);
  }

  // Two boundaries of different causes exchange their order: theta_a - theta_b changes sign.
  std::optional<EventFunction> crossing(const RegimeStructure& lo, const RegimeStructure& hi) const {
    const std::size_t n = lo.roots.size();
    std::size_t i = 0;
    while (i < n && lo.roots[i].cause == hi.roots[i].cause) ++i;
    if (i + 1 >= n) return std::nullopt;
    const BoundaryCause a = lo.roots[i].cause, b = lo.roots[i + 1].cause;
    if (hi.roots[i].cause != b || hi.roots[i + 1].cause != a) return std::nullopt;
    for (std::size_t k = i + 2; k < n; ++k)
      if (lo.roots[k].cause != hi.roots[k].cause) return std::nullopt;
    int ia = 0, ib = 0;
    for (std::size_t k = 0; k < i; ++k) {
      ia += lo.roots[k].cause == a;
      ib += lo.roots[k].cause == b;
    }
    auto g = [this, a, b, ia, ib](double v) {
      const RegimeStructure s = structure(v);
      return nth_root(s, a, ia) - nth_root(s, b, ib);
    };
    auto theta = [this, a, ia](double v) { return nth_root(structure(v), a, ia); };
    return EventFunction{EventKind::crossing, {a, b}, g, theta};
  }

  // A pair of zeros of one function is born or dies: the extremum of that function between
  // them changes sign.
  std::optional<EventFunction> fold(const RegimeStructure& lo, const RegimeStructure& hi,
                                    BoundaryCause c) const {
    const bool lo_has_pair = count(lo, c) > count(hi, c);
    const RegimeStructure& big = lo_has_pair ? lo : hi;
    const RegimeStructure& small = lo_has_pair ? hi : lo;
    std::vector<double> zeros;
    for (const auto& r : big.roots)
      if (r.cause == c) zeros.push_back(r.theta);
    int best = -1;
    for (int j = 0; j + 1 < static_cast<int>(zeros.size()); ++j) {
      // Removing zeros j, j+1 of cause c from `big` must give the sequence of `small`.
      std::vector<BoundaryCause> seq;
      for (const auto& r : big.roots)
        if (!(r.cause == c && (r.theta == zeros[j] || r.theta == zeros[j + 1])))
          seq.push_back(r.cause);
      bool ok = seq.size() == small.roots.size();
      for (std::size_t k = 0; ok && k < seq.size(); ++k) ok = seq[k] == small.roots[k].cause;
      if (ok && (best < 0 || zeros[j + 1] - zeros[j] < zeros[best + 1] - zeros[best])) best = j;
    }
    if (best < 0) return std::nullopt;
    const double z0 = zeros[best], z1 = zeros[best + 1], gap = z1 - z0;
    const double wlo = std::max({best > 0 ? 0.5 * (zeros[best - 1] + z0) : 1e-6, z0 - 0.25 - 2 * gap});
    const double whi = std::min(
        {best + 2 < static_cast<int>(zeros.size()) ? 0.5 * (z1 + zeros[best + 2]) : kPi,
         z1 + 0.25 + 2 * gap});
    const double big_value = lo_has_pair ? lo_value_ : hi_value_;
    const double sigma = functions(big_value)(0.5 * (z0 + z1))[c] > 0.0 ? 1.0 : -1.0;
    // g(v) = max over the window of sigma f_c(theta; v): > 0 where the pair exists.
    auto extremum = [this, c, sigma, wlo, whi](double v) {
      const RegimeFunctions f = functions(v);
      std::uintmax_t it = 200;
      return boost::math::tools::brent_find_minima(
          [&](double t) { return -sigma * f(t)[c]; }, wlo, whi,
          std::numeric_limits<double>::digits / 2, it);
    };
    auto g = [extremum](double v) { return -extremum(v).second; };
    auto theta = [extremum](double v) { return extremum(v).first; };
    return EventFunction{EventKind::fold, {c}, g, theta};
  }

  // Zeros enter or leave through theta = pi: f_c(pi) changes sign.
  std::optional<EventFunction> edge_entry(const std::vector<BoundaryCause>& changed) const {
    for (BoundaryCause c : changed) {
      const double flo = functions(lo_value_)(kPi)[c], fhi = functions(hi_value_)(kPi)[c];
      if ((flo < 0.0) != (fhi < 0.0)) {
        auto g = [this, c](double v) { return functions(v)(kPi)[c]; };
        return EventFunction{EventKind::band_edge_entry, changed, g, [](double) { return kPi; }};
      }
    }
    return std::nullopt;
  }

  void isolate(double lo, double hi, const RegimeStructure& slo, const RegimeStructure& shi,
               int depth, std::vector<RegimeEvent>& out) {
    lo_value_ = lo;
    hi_value_ = hi;
    if (auto ev = classify(slo, shi)) {
      const double glo = ev->g(lo), ghi = ev->g(hi);
      if (std::isfinite(glo) && std::isfinite(ghi) && (glo < 0.0) != (ghi < 0.0)) {
        const double tol = o_.value_tolerance * std::max(std::abs(lo), 1e-300);
        const double v = solve_bracketed(ev->g, lo, hi, glo, ghi, tol);
        out.push_back({v, ev->theta_at(v), ev->kind, ev->causes,
                       static_cast<int>(slo.intervals.size()),
                       static_cast<int>(shi.intervals.size())});
        return;
      }
    }
    const double mid = 0.5 * (lo + hi);
    if (depth >= o_.max_depth || hi - lo <= o_.value_tolerance * std::abs(hi)) {
      std::vector<BoundaryCause> causes;
      for (BoundaryCause c : kSmoothCauses)
        if (count(slo, c) != count(shi, c)) causes.push_back(c);
      out.push_back({mid, std::numeric_limits<double>::quiet_NaN(), EventKind::unresolved, causes,
                     static_cast<int>(slo.intervals.size()), static_cast<int>(shi.intervals.size())});
      return;
    }
    const RegimeStructure smid = structure(mid);
    if (!same_sequence(slo, smid)) isolate(lo, mid, slo, smid, depth + 1, out);
    if (!same_sequence(smid, shi)) isolate(mid, hi, smid, shi, depth + 1, out);
  }

 private:
  const RegimeFamily& family_;
  EventOptions o_;
  double lo_value_ = 0, hi_value_ = 0;
};

}  // namespace

std::vector<RegimeEvent> regime_events(const Params& base, Branch b, ParameterAxis axis,
                                       const GridAxis& scan, const EventOptions& options) {
  validate(base);
  validate(scan, to_string(axis).data());
  if (!(scan.lo > 0.0)) throw InvalidParameter(std::string(to_string(axis)), "scan must lie in > 0");
  const RegimeFamily family = [&base, b, axis](double value) {
    return regime_functions(with_parameter(base, axis, value), b);
  };
  return regime_events(family, scan, options);
}

// Structures on the scan grid, then every neighbouring pair that differs isolated to its events.
std::vector<RegimeEvent> regime_events(const RegimeFamily& family, const GridAxis& scan,
                                       const EventOptions& options) {
  EventFinder finder(family, options);
  std::vector<RegimeStructure> s(scan.n);
#pragma omp parallel for schedule(dynamic)
  for (int i = 0; i < scan.n; ++i) s[i] = finder.structure(scan.at(i));
  std::vector<RegimeEvent> events;
  for (int i = 0; i + 1 < scan.n; ++i)
    if (!same_sequence(s[i], s[i + 1]))
      finder.isolate(scan.at(i), scan.at(i + 1), s[i], s[i + 1], 0, events);
  std::sort(events.begin(), events.end(),
            [](const RegimeEvent& x, const RegimeEvent& y) { return x.value < y.value; });
  return events;
}

}  // namespace lrchain::regime

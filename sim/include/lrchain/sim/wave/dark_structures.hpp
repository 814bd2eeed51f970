#pragma once
// Dark structures on a ring (docs/waves.md, "The fate of a wave"): localized dips of the energy
// envelope in an intact background, the mark of dark breathers (the defocusing NLS's dark soliton
// |A|^2 = A0^2 [1 - d sech^2(x / l)], black for d = 1: A0^2 tanh^2(x / l)).
//   envelope     a_n = running mean of |e_n| over an odd window of about one carrier wavelength 2 pi / theta
//                (it averages out the ripple of a travelling wave's energy density at 2 theta);
//   background   b = the median of a_n;
//   dip          a maximal run of sites with a_n < (1 - kDarkDepth / 2) b (it ends where the envelope returns
//                halfway from the dip level to the background) reaching below (1 - kDarkDepth) b; its depth
//                d = 1 - min a / b and its
//                width the full width at half depth (where a = b (1 - d / 2), linearly interpolated):
//                1.763 l for the NLS profile, black or grey;
//   structure    a dip whose width is at most kDarkWidthShare of the distance to the nearest other dip
//                (of N when alone): a sinusoidal modulation of the envelope spends half its period below
//                its mid level, so no dip of a modulated wave passes;
//   intact       the background outside the dips (each widened by its width on both sides) has a relative
//                interquartile range (q3 - q1) / b <= kDarkBackgroundSpread; else no structure is counted.
// Thresholds: kDarkDepth = 1/2 counts black solitons and grey ones moving slower than c_s / sqrt(2)
// relative to the carrier's group velocity (d = 1 - v^2 / c_s^2); kDarkBackgroundSpread = 1/5 rejects a
// thermalised ring (site energies exponential, their mean over W sites Gamma(W) distributed: relative
// interquartile range ~ 1.35 / sqrt(W), above 1/5 for every window W < 45, i.e. theta > 0.14) and admits a
// wave whose envelope is modulated by less than 7 % (1 + 2 m cos: range 2.83 m).
#include <vector>

#include "lrchain/index.hpp"

namespace lrchain::sim::wave {

inline constexpr double kDarkDepth = 0.5;             // a dip reaches below half the background
inline constexpr double kDarkWidthShare = 0.25;       // its width at most a quarter of the spacing to the next dip
inline constexpr double kDarkBackgroundSpread = 0.2;  // background's (q3 - q1) / median at most this
inline constexpr double kTanhHalfDepthWidth = 1.7627471740390860;  // 2 atanh(1/sqrt 2) = 2 acosh(sqrt 2): FWHM / l of sech^2

struct DarkStructure {
  double centre = 0;  // site of the envelope's minimum
  double width = 0;   // full width at half depth, sites
  double depth = 0;   // 1 - min a / b
  double left = 0, right = 0;  // the half-depth crossings (centre - left + right = width; may lie off [0, N))
};

// The envelope window for carrier wavenumber theta: 2 floor(pi / theta) + 1 sites, the odd number within one
// of the wavelength 2 pi / theta (at least 3).
Index envelope_window(double theta);

// Finds the dark structures of an energy density on a ring; buffers made once (nothing allocates per scan).
class DarkStructureScan {
 public:
  DarkStructureScan(Index sites, Index window);
  // Scans e (sites entries); returns the number of structures counted (0 when the background is not intact).
  Index scan(const double* e);
  const std::vector<DarkStructure>& structures() const { return structures_; }  // counted, deepest first
  double background() const { return background_; }          // b
  double background_spread() const { return spread_; }       // (q3 - q1) / b outside the dips
  const std::vector<double>& envelope() const { return envelope_; }

 private:
  Index window_;
  std::vector<double> envelope_, sorted_;
  std::vector<char> dip_;  // sites inside a widened dip
  std::vector<DarkStructure> candidates_, structures_;
  double background_ = 0, spread_ = 0;
};

}  // namespace lrchain::sim::wave

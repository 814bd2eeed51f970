// The integer options' caps shared by the command and the Python module (config/option_caps.hpp).
#include "lrchain/config/option_caps.hpp"

#include <cmath>

#include "lrchain/checked_number.hpp"

namespace lrchain::config {

const std::vector<OptionCap>& option_caps() {
  static const std::vector<OptionCap> caps{dark_sites,  dark_points,       dark_samples, dark_periods,
                                           ring_sites,  intervals_samples, map_pixels_x, map_pixels_y};
  return caps;
}

std::int64_t checked_option(double value, const OptionCap& cap, const std::string& parameter) {
  return checked_integer(value, parameter, cap.least, cap.most);
}

std::int64_t checked_option_count(double time, double unit, const OptionCap& cap, const std::string& parameter) {
  return checked_count(std::floor(time / unit), parameter, cap.least, cap.most,
                       "periods (" + std::string(cap.option) + " / " + std::string(cap.counted) + ")");
}

}  // namespace lrchain::config

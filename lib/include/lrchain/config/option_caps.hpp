#pragma once
// The caps of the integer options that the `lrchain` command and the Python module share: one table,
// read by the command's option parsers (cli/src/*_command.cpp) and by the Python bindings
// (python/src/*_binding.cpp), so that a cap cannot differ between them. Python lists the table as
// lrchain._lrchain.option_caps() (a test refuses cap * 10 through both).
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace lrchain::config {

// An integer option in [least, most]. `counted` is empty when the option's value is the integer;
// otherwise the option is a time and the integer is the count of that unit it spans ("T_b": t-end /
// T_b periods). `python` names the Python function and keyword taking it ("dark.evolve samples").
struct OptionCap {
  std::string_view command;  // the subcommand: "dark evolve"
  std::string_view option;   // the command's option without "--": "samples"
  std::int64_t least, most;
  std::string_view counted;
  std::string_view python;
};

inline constexpr std::int64_t int32_most = 2'147'483'647;

inline constexpr OptionCap dark_sites{"dark solve", "sites", 9, int32_most, "", "dark.solve sites"};
inline constexpr OptionCap dark_points{"dark continue", "points", 1, 1'000'000, "", "dark.continue_branch points"};
inline constexpr OptionCap dark_samples{"dark evolve", "samples", 4, 1'000'000, "", "dark.evolve samples"};
inline constexpr OptionCap dark_periods{"dark evolve", "t-end", 1, int32_most, "T_b", "dark.evolve t_end"};
inline constexpr OptionCap ring_sites{"simulate ring", "sites", 8, 1'000'000, "", "simulate.ring sites"};
inline constexpr OptionCap intervals_samples{"regime intervals", "samples", 8, 10'000'000, "",
                                             "regime.intervals samples"};
inline constexpr OptionCap map_pixels_x{"regime map", "nx", 2, 20'000, "", "regime.theta_rho_map rho"};
inline constexpr OptionCap map_pixels_y{"regime map", "ny", 2, 20'000, "", "regime.theta_rho_map theta"};

// Every cap above, in that order.
const std::vector<OptionCap>& option_caps();

// `value` as an integer in [cap.least, cap.most], else InvalidParameter naming `parameter` (the
// message of lrchain::checked_integer: "must be an integer in [least, most]").
std::int64_t checked_option(double value, const OptionCap& cap, const std::string& parameter);

// The count floor(time / unit) of a `counted` cap in [cap.least, cap.most], else InvalidParameter
// naming `parameter` ("gives periods (t-end / T_b) outside [1, 2147483647]").
std::int64_t checked_option_count(double time, double unit, const OptionCap& cap, const std::string& parameter);

}  // namespace lrchain::config

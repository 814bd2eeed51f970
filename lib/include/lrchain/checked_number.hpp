#pragma once
// The one way a user's number becomes an integer (a count, a size, a number of steps or samples):
// refuses NaN, inf, non-integral values where an integer is asked for, and anything outside
// [min, max], with InvalidParameter naming the parameter. Never a float-to-integer overflow.
#include <cstdint>
#include <string>

namespace lrchain {

// `value` must be an integer in [min, max] (1e3 is accepted as 1000).
std::int64_t checked_integer(double value, const std::string& parameter, std::int64_t min, std::int64_t max);

// ceil(value) for a count derived from user values (e.g. t_end / sample_every): `value` must be
// finite and ceil(value) must lie in [min, max]; `what` explains the count in the message.
std::int64_t checked_count(double value, const std::string& parameter, std::int64_t min, std::int64_t max,
                           const std::string& what);

// `value` must be finite (not NaN or +-inf).
double checked_finite(double value, const std::string& parameter);

}  // namespace lrchain

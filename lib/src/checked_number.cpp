// Checked conversions of user numbers to integers (checked_number.hpp).
#include "lrchain/checked_number.hpp"

#include <cmath>
#include <string>

#include "lrchain/errors.hpp"

namespace lrchain {

namespace {

std::string range_text(std::int64_t min, std::int64_t max) {
  return "[" + std::to_string(min) + ", " + std::to_string(max) + "]";
}

// True when the finite double v lies in [min, max] (compared in long double: exact for int64 bounds).
bool in_range(double v, std::int64_t min, std::int64_t max) {
  return static_cast<long double>(v) >= static_cast<long double>(min) &&
         static_cast<long double>(v) <= static_cast<long double>(max);
}

}  // namespace

std::int64_t checked_integer(double value, const std::string& parameter, std::int64_t min, std::int64_t max) {
  if (!std::isfinite(value) || value != std::floor(value) || !in_range(value, min, max))
    throw InvalidParameter(parameter, "must be an integer in " + range_text(min, max));
  return static_cast<std::int64_t>(value);
}

std::int64_t checked_count(double value, const std::string& parameter, std::int64_t min, std::int64_t max,
                           const std::string& what) {
  const double c = std::ceil(value);
  if (!std::isfinite(value) || !in_range(c, min, max))
    throw InvalidParameter(parameter, "gives " + what + " outside " + range_text(min, max));
  return static_cast<std::int64_t>(c);
}

double checked_finite(double value, const std::string& parameter) {
  if (!std::isfinite(value)) throw InvalidParameter(parameter, "must be a finite number");
  return value;
}

}  // namespace lrchain

#pragma once
// The one shared parser for numeric command-line / config values:
// plain decimals ("0.25", "1e-3"), fractions ("1/3", "4/9"), multiples of pi
// ("pi", "pi/2", "3*pi/5", "-pi/4", "2pi"). Not an expression evaluator.
#include <string>
#include <string_view>

namespace lrchain {

// Throws InvalidParameter(parameter, ...) if text is not one of the accepted forms or is NaN/inf.
double parse_number(std::string_view text, const std::string& parameter);

}  // namespace lrchain

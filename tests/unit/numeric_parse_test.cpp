// The shared numeric option parser (issue 2, section 4): decimals, fractions, multiples of pi.
#include <doctest/doctest.h>

#include <numbers>

#include "lrchain/errors.hpp"
#include "lrchain/numeric_parse.hpp"

using lrchain::parse_number;
constexpr double pi = std::numbers::pi;

TEST_CASE("accepted forms") {
  CHECK(parse_number("0.25", "x") == 0.25);
  CHECK(parse_number("1e-3", "x") == 1e-3);
  CHECK(parse_number("-2", "x") == -2.0);
  CHECK(parse_number("1/3", "x") == 1.0 / 3.0);
  CHECK(parse_number("4/9", "x") == 4.0 / 9.0);
  CHECK(parse_number("pi", "x") == pi);
  CHECK(parse_number("pi/2", "x") == pi / 2);
  CHECK(parse_number("3*pi/5", "x") == 3 * pi / 5);
  CHECK(parse_number("-pi/4", "x") == -pi / 4);
  CHECK(parse_number("2pi", "x") == 2 * pi);
  CHECK(parse_number(" 3 * pi / 5 ", "x") == 3 * pi / 5);
}

TEST_CASE("rejected forms name the parameter") {
  for (const char* bad : {"", "abc", "nan", "NaN", "inf", "1/0", "1/", "/2", "pi*2", "1+1", "2**pi", "sqrt(2)", "1/3/4"})
    CHECK_THROWS_WITH_AS(parse_number(bad, "theta"), doctest::Contains("theta"), lrchain::InvalidParameter);
}

TEST_CASE("a multiple of pi or a fraction beyond the largest double is refused as out of range") {
  // 1e308 * pi and 1e308 / 1e-10 overflow to inf; the parser must not hand inf on.
  for (const char* big : {"1e308pi", "-1e308*pi", "1e308pi/2", "1e308/1e-10"})
    CHECK_THROWS_WITH_AS(parse_number(big, "rho"), doctest::Contains("rho: '"), lrchain::InvalidParameter);
  CHECK_THROWS_WITH_AS(parse_number("1e308pi", "rho"), doctest::Contains("out of range"), lrchain::InvalidParameter);
  CHECK(parse_number("1e300pi", "x") == 1e300 * pi);  // large but finite: the parameter's range decides
}

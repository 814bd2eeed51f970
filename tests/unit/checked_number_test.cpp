// checked_integer / checked_count (lrchain/checked_number.hpp): no float-to-integer overflow.
#include <doctest/doctest.h>

#include <cmath>
#include <limits>

#include "lrchain/checked_number.hpp"
#include "lrchain/errors.hpp"

using lrchain::checked_count;
using lrchain::checked_integer;
using lrchain::InvalidParameter;

TEST_CASE("checked_integer accepts integral values in range, 1e3 included") {
  CHECK(checked_integer(1e3, "N", 1, 1000000) == 1000);
  CHECK(checked_integer(-3, "k", -5, 5) == -3);
}

TEST_CASE("checked_integer refuses NaN, inf, fractions and out-of-range values, naming the parameter") {
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  for (double bad : {nan, inf, -inf, 1.5, 1e300, -1.0, 0.0, 9.3e18})
    CHECK_THROWS_WITH_AS(checked_integer(bad, "N", 1, 1000000), doctest::Contains("N"), InvalidParameter);
}

TEST_CASE("checked_count rounds up and refuses counts beyond the limit") {
  CHECK(checked_count(10.2, "periods", 1, 100, "samples") == 11);
  CHECK_THROWS_WITH_AS(checked_count(1e300 * M_PI, "periods", 1, 100, "samples"), doctest::Contains("periods"),
                       InvalidParameter);
  CHECK_THROWS_AS(checked_count(std::nan(""), "t_end", 1, 100, "samples"), InvalidParameter);
}

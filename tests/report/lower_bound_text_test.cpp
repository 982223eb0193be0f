// Printed lower bounds never overstate the bound (compared as exact rationals).
#include "grpvss/report/lower_bound_text.hpp"

#include <algorithm>
#include <random>
#include <string>

#include <boost/multiprecision/cpp_int.hpp>
#include <gtest/gtest.h>

namespace grpvss::report {
namespace {

using Rational = boost::multiprecision::cpp_rational;

// "-12.3456" -> -123456 / 10^4, exactly.
Rational decimal_value(const std::string& text) {
  const bool negative = !text.empty() && text[0] == '-';
  std::string digits;
  int decimals = 0;
  bool after_point = false;
  for (char c : text.substr(negative ? 1 : 0)) {
    if (c == '.') {
      after_point = true;
    } else {
      digits += c;
      if (after_point) ++decimals;
    }
  }
  // Leading zeros would make cpp_int read the digits as octal.
  const std::size_t first = std::min(digits.find_first_not_of('0'), digits.size() - 1);
  Rational value{boost::multiprecision::cpp_int(digits.substr(first))};
  for (int k = 0; k < decimals; ++k) value /= 10;
  return negative ? -value : value;
}

TEST(FormatLowerBound, HandNumbers) {
  EXPECT_EQ(format_lower_bound(0.04356, 4), "0.0435");  // "{:.4f}" would print 0.0436
  EXPECT_EQ(format_lower_bound(0.04354, 4), "0.0435");
  EXPECT_EQ(format_lower_bound(0.5, 4), "0.5000");
  EXPECT_EQ(format_lower_bound(0.0, 4), "0.0000");
  EXPECT_EQ(format_lower_bound(-0.00004, 4), "-0.0001");
  EXPECT_EQ(format_lower_bound(16.49999, 2), "16.49");
  EXPECT_THROW(format_lower_bound(1.0, 10), std::invalid_argument);
}

TEST(FormatLowerBound, NeverAboveTheValueAndWithinOneUnit) {
  std::mt19937_64 rng(7545);
  std::uniform_real_distribution<double> magnitude(-6.0, 7.0);
  std::uniform_int_distribution<int> decimals(0, 6);
  for (int k = 0; k < 20000; ++k) {
    const double value = (k % 2 ? -1.0 : 1.0) * std::pow(10.0, magnitude(rng));
    const int d = decimals(rng);
    const std::string text = format_lower_bound(value, d);
    const Rational printed = decimal_value(text), exact(value);
    Rational unit(1);
    for (int i = 0; i < d; ++i) unit /= 10;
    ASSERT_LE(printed, exact) << value << " " << d << " " << text;
    ASSERT_LT(exact - printed, unit) << value << " " << d << " " << text;
  }
}

}  // namespace
}  // namespace grpvss::report

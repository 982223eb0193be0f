#include "grpvss/geometry/directed_rounding.hpp"

#include <cmath>
#include <limits>
#include <random>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

namespace grpvss::geometry::rounding {
namespace {

// Exact reference: with round-to-nearest, TwoSum / fma give the exact rounding error e of
// s = fl(x op y); the upward-rounded result is s if e <= 0, else the next double up.
double expected_up(double s, double e) { return e > 0 ? std::nextafter(s, INFINITY) : s; }
double expected_down(double s, double e) { return e < 0 ? std::nextafter(s, -INFINITY) : s; }

void two_sum(double a, double b, double& s, double& e) {
  s = a + b;
  const double bb = s - a;
  e = (a - (s - bb)) + (b - bb);
}

TEST(DirectedRounding, SumsAndProductsMatchTheExactErrorReference) {
  std::mt19937_64 rng(1);
  std::uniform_real_distribution<double> mantissa(-1.0, 1.0);
  std::uniform_int_distribution<int> exponent(-30, 30);
  for (int trial = 0; trial < 100000; ++trial) {
    const double a = std::ldexp(mantissa(rng), exponent(rng));
    const double b = std::ldexp(mantissa(rng), exponent(rng));
    double s, e;
    two_sum(a, b, s, e);
    const double p = a * b;
    const double pe = std::fma(a, b, -p);
    double up_sum, down_sum, up_product, down_product, up_difference, down_difference;
    {
      const UpwardRoundingScope upward;
      up_sum = add_up(a, b);
      down_sum = add_down(a, b);
      up_difference = sub_up(a, -b);
      down_difference = sub_down(a, -b);
      up_product = mul_up(a, b);
      down_product = mul_down(a, b);
    }
    ASSERT_EQ(up_sum, expected_up(s, e)) << a << " + " << b;
    ASSERT_EQ(down_sum, expected_down(s, e)) << a << " + " << b;
    ASSERT_EQ(up_difference, expected_up(s, e));
    ASSERT_EQ(down_difference, expected_down(s, e));
    ASSERT_EQ(up_product, expected_up(p, pe)) << a << " * " << b;
    ASSERT_EQ(down_product, expected_down(p, pe)) << a << " * " << b;
  }
  EXPECT_EQ(std::fegetround(), FE_TONEAREST);  // the scope restored the mode
}

TEST(DirectedRounding, SquareRootsBracketTheExactRoot) {
  std::mt19937_64 rng(2);
  std::uniform_real_distribution<double> value(0.0, 1e6);
  for (int trial = 0; trial < 100000; ++trial) {
    const double x = value(rng);
    double up, down;
    {
      const UpwardRoundingScope upward;
      up = sqrt_up(x);
      down = sqrt_down(x);
    }
    // r*r compared with x exactly: fma gives the exact residual sign.
    EXPECT_GE(std::fma(up, up, -x), 0.0) << x;
    EXPECT_LE(std::fma(down, down, -x), 0.0) << x;
    EXPECT_LE(up - down, 3 * std::ldexp(std::sqrt(x), -52));
  }
}

}  // namespace
}  // namespace grpvss::geometry::rounding

namespace grpvss::geometry::rounding {
namespace {

// The nearest-mode sums (no rounding-mode switch) must equal the hardware's directed
// rounding bit for bit, including cancellation, exact sums and overflow.
TEST(DirectedRounding, NearestModeSumsEqualTheHardwareDirectedSums) {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> mantissa(-1.0, 1.0);
  std::uniform_int_distribution<int> exponent(-60, 60);
  std::vector<std::pair<double, double>> cases = {
      {1.0, 0x1p-60}, {1.0, -0x1p-60}, {0.5, 0.25}, {1e308, 1e308}, {-1e308, -1e308},
      {std::numeric_limits<double>::max(), 1e292}, {0.0, -0.0}, {3.0, -3.0}};
  for (int trial = 0; trial < 100000; ++trial) {
    cases.emplace_back(std::ldexp(mantissa(rng), exponent(rng)),
                       std::ldexp(mantissa(rng), exponent(rng)));
  }
  for (const auto& [a, b] : cases) {
    const double down = nearest_mode_add_down(a, b);
    const double up = nearest_mode_add_up(a, b);
    const double difference_down = nearest_mode_sub_down(a, -b);
    ASSERT_EQ(std::fegetround(), FE_TONEAREST);
    double hardware_down, hardware_up;
    {
      const UpwardRoundingScope upward;
      hardware_down = add_down(a, b);
      hardware_up = add_up(a, b);
    }
    ASSERT_EQ(down, hardware_down) << a << " + " << b;
    ASSERT_EQ(up, hardware_up) << a << " + " << b;
    ASSERT_EQ(difference_down, hardware_down) << a << " - " << -b;
  }
}

}  // namespace
}  // namespace grpvss::geometry::rounding

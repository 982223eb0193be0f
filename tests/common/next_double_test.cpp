#include "grpvss/common/next_double.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

namespace grpvss {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

std::uint64_t bits_of(double x) {
  std::uint64_t bits = 0;
  std::memcpy(&bits, &x, sizeof bits);
  return bits;
}

double from_bits(std::uint64_t bits) {
  double x = 0.0;
  std::memcpy(&x, &bits, sizeof x);
  return x;
}

// Bit-identical (so -0.0 and +0.0 differ, and NaN matches NaN by pattern class).
void expect_same_double(double expected, double actual, double x) {
  if (std::isnan(expected)) {
    EXPECT_TRUE(std::isnan(actual)) << "x = " << x;
    return;
  }
  EXPECT_EQ(bits_of(expected), bits_of(actual)) << "x = " << x << ": " << expected << " vs " << actual;
}

void expect_like_nextafter(double x) {
  expect_same_double(std::nextafter(x, kInf), next_up(x), x);
  expect_same_double(std::nextafter(x, -kInf), next_down(x), x);
  if (x != 0.0 && !std::isnan(x)) expect_same_double(std::nextafter(x, 0.0), next_toward_zero(x), x);
}

TEST(NextDouble, MatchesNextafterOnTheSpecialValues) {
  const double specials[] = {0.0,
                             -0.0,
                             std::numeric_limits<double>::denorm_min(),
                             -std::numeric_limits<double>::denorm_min(),
                             std::numeric_limits<double>::min(),
                             -std::numeric_limits<double>::min(),
                             from_bits(0x000fffffffffffffULL),  // the largest subnormal
                             1.0,
                             -1.0,
                             std::numeric_limits<double>::max(),
                             -std::numeric_limits<double>::max(),
                             kInf,
                             -kInf,
                             std::numeric_limits<double>::quiet_NaN()};
  for (const double x : specials) expect_like_nextafter(x);
  EXPECT_EQ(next_toward_zero(0.0), 0.0);
  EXPECT_EQ(next_up(1.0), 1.0 + std::numeric_limits<double>::epsilon());
  EXPECT_EQ(bits_of(next_up(-std::numeric_limits<double>::denorm_min())), bits_of(-0.0));
  EXPECT_EQ(next_up(std::numeric_limits<double>::max()), kInf);
  EXPECT_EQ(next_down(-kInf), -kInf);
}

TEST(NextDouble, MatchesNextafterOnRandomBitPatterns) {
  std::mt19937_64 random(20261127);
  for (int i = 0; i < 200000; ++i) {
    const double x = from_bits(random());
    expect_like_nextafter(x);
  }
  // And on ordinary magnitudes, where the verifier uses it (1e-9 .. 1e3 m).
  std::uniform_real_distribution<double> exponent(-30.0, 10.0);
  for (int i = 0; i < 200000; ++i) {
    const double x = (i % 2 == 0 ? 1.0 : -1.0) * std::exp2(exponent(random));
    expect_like_nextafter(x);
  }
}

}  // namespace
}  // namespace grpvss

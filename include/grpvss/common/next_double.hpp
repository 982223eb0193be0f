#pragma once
/// \file
/// \brief The neighbouring doubles of a double, from its bit pattern.
///
/// Bit-identical to `std::nextafter(x, ±infinity)`, but inline: the certified step's radius
/// and motion-bound sums round up one ulp per term, and the libm call was ~2.5% of a UR5e
/// trajectory (docs/performance.md). IEEE 754 orders the positive doubles like their bit
/// patterns, so the next double above a positive x is the next bit pattern; the negative ones
/// mirror it. Independent of the rounding mode.

#include <cstdint>
#include <cstring>
#include <limits>

namespace grpvss {

/// \brief The smallest double above \p x: `std::nextafter(x, +infinity)` (NaN and +infinity
/// are returned unchanged, either zero gives the smallest subnormal).
inline double next_up(double x) {
  if (!(x < std::numeric_limits<double>::infinity())) return x;
  std::uint64_t bits = 0;
  std::memcpy(&bits, &x, sizeof bits);
  // Either zero steps from +0's pattern to 1, the smallest subnormal, by the integer path: a
  // subnormal constant is what GCC loads through the x87 unit, and storing it as a double
  // costs a microcode assist each time (19% of a UR5e trajectory: docs/performance.md#x87-subnormal).
  if (x == 0.0) bits = 0;
  bits = x >= 0.0 ? bits + 1 : bits - 1;  // a negative x moves toward zero
  std::memcpy(&x, &bits, sizeof bits);
  return x;
}

/// \brief The largest double below \p x: `std::nextafter(x, -infinity)`.
inline double next_down(double x) { return -next_up(-x); }

/// \brief The double next to \p x toward zero (`std::nextafter(x, 0.0)` for x != 0; 0 stays).
inline double next_toward_zero(double x) {
  if (x > 0.0) return next_down(x);
  if (x < 0.0) return next_up(x);
  return x;
}

}  // namespace grpvss

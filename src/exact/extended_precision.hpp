#pragma once
/// \file
/// \brief Whether `long double` arithmetic here and now is what the extended-precision
/// filters' error bounds assume: a 64-bit significand, rounding to nearest.
/// proof: proofs/interference.md#crossing-by-error-bound, proofs/placed-hull.md (H1)

#include <cfenv>
#include <limits>

namespace grpvss::geometry {

/// \brief True when `long double` operations round to nearest with a 64-bit significand: the
/// type has one, the rounding mode (fegetround) is to nearest, and on x87 the precision
/// control of the FPU control word is extended (a library may set it to double, after which
/// long double results are rounded to 53 bits whatever the type says).
inline bool extended_precision_rounds_to_nearest() {
  if constexpr (std::numeric_limits<long double>::digits < 64) {
    return false;
  } else {
    if (std::fegetround() != FE_TONEAREST) return false;
#if (defined(__x86_64__) || defined(__i386__)) && defined(__GNUC__)
    unsigned short control = 0;
    __asm__ volatile("fnstcw %0" : "=m"(control));
    if (((control >> 8) & 3) != 3) return false;  // precision control: 11 = 64-bit significand
#endif
    return true;
  }
}

}  // namespace grpvss::geometry

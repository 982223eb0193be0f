// The unit roundoff of double and Higham's gamma_n, shared by the forward-kinematics and cell
// placement error bounds (proofs/fk-rounding.md).
#pragma once

#include <limits>

namespace grpvss {

inline constexpr double kUnitRoundoff = std::numeric_limits<double>::epsilon() / 2;  // u = 2^-53

// gamma_n = n u / (1 - n u): bounds the relative error of n rounded operations (n u < 1).
inline double gamma(int n) { return n * kUnitRoundoff / (1 - n * kUnitRoundoff); }

}  // namespace grpvss

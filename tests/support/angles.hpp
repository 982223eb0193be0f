#pragma once
// Pi and degrees to radians for the tests, defined once so that the tests' unity batches
// (tests/CMakeLists.txt) hold one definition.

namespace grpvss::test {

inline constexpr double kPi = 3.14159265358979323846;

/// `degrees` in radians.
inline double deg(double degrees) { return degrees * kPi / 180.0; }

}  // namespace grpvss::test

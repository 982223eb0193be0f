#pragma once
/// \file
/// \brief Degrees exist only at the I/O boundary: the one conversion used by every reader.

namespace grpvss::io {

/// \f$\pi/180\f$ rounded to double.
inline constexpr double kRadiansPerDegree = 3.14159265358979323846 / 180.0;

/// Degrees (as written in thesis files) to radians (library unit): one rounded product.
constexpr double degrees_to_radians(double degrees) { return degrees * kRadiansPerDegree; }

}  // namespace grpvss::io

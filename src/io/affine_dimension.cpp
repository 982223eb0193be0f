#include "affine_dimension.hpp"

#include <array>
#include <climits>
#include <cmath>
#include <cstdint>

// GCC 12 reports a false -Wmaybe-uninitialized inside cpp_int's small-buffer storage.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#include <boost/multiprecision/cpp_int.hpp>
#pragma GCC diagnostic pop

namespace grpvss::io {
namespace {

using boost::multiprecision::cpp_int;
using IntPoint = std::array<cpp_int, 3>;

/// A finite double is m 2^(e-53) with an integer |m| < 2^53 (frexp). Returns e - 53.
int lowest_exponent(double x) {
  int exponent = 0;
  std::frexp(x, &exponent);
  return exponent - 53;
}

/// x 2^(-shift) as an exact integer; requires shift <= lowest_exponent(x) (or x == 0).
cpp_int scaled_integer(double x, int shift) {
  if (x == 0.0) return 0;
  int exponent = 0;
  const double mantissa = std::frexp(x, &exponent);
  // |mantissa| in [0.5, 1): times 2^53 it is an integer below 2^53, exactly representable.
  cpp_int value = static_cast<std::int64_t>(std::ldexp(mantissa, 53));
  return value << (exponent - 53 - shift);
}

IntPoint to_integer(const Eigen::Vector3d& p, int shift) {
  return {scaled_integer(p.x(), shift), scaled_integer(p.y(), shift),
          scaled_integer(p.z(), shift)};
}

IntPoint minus(const IntPoint& a, const IntPoint& b) {
  return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}

IntPoint cross(const IntPoint& u, const IntPoint& v) {
  return {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
}

bool is_zero(const IntPoint& u) { return u[0] == 0 && u[1] == 0 && u[2] == 0; }

cpp_int dot(const IntPoint& u, const IntPoint& v) {
  return u[0] * v[0] + u[1] * v[1] + u[2] * v[2];
}

}  // namespace

int affine_dimension(const std::vector<Eigen::Vector3d>& points) {
  if (points.empty()) return -1;
  // One common scale 2^shift makes every coordinate an integer: no rounding anywhere below.
  int shift = INT_MAX;
  for (const Eigen::Vector3d& p : points) {
    for (int axis = 0; axis < 3; ++axis) {
      if (!std::isfinite(p[axis])) throw std::logic_error("affine_dimension: non-finite point");
      if (p[axis] != 0.0) shift = std::min(shift, lowest_exponent(p[axis]));
    }
  }
  if (shift == INT_MAX) shift = 0;  // every coordinate is zero

  const Eigen::Vector3d& first = points.front();
  std::size_t second = 1;
  while (second < points.size() && points[second] == first) ++second;  // exact in double
  if (second == points.size()) return 0;

  const IntPoint p0 = to_integer(first, shift);
  const IntPoint u = minus(to_integer(points[second], shift), p0);
  IntPoint normal;
  std::size_t third = second + 1;
  for (; third < points.size(); ++third) {
    normal = cross(u, minus(to_integer(points[third], shift), p0));
    if (!is_zero(normal)) break;
  }
  if (third >= points.size()) return 1;

  // orient3d(p0, p1, p2, p) = normal . (p - p0), normal = (p1 - p0) x (p2 - p0).
  for (std::size_t fourth = third + 1; fourth < points.size(); ++fourth) {
    if (dot(normal, minus(to_integer(points[fourth], shift), p0)) != 0) return 3;
  }
  return 2;
}

}  // namespace grpvss::io

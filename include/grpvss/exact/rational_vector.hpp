#pragma once
/// \file
/// \brief Exact 3-vectors of GMP rationals: the arithmetic the shape-containment checks decide
/// in (doubles convert exactly; +, -, * never round).

#include <array>

#include <Eigen/Core>
#include <gmpxx.h>

#include "grpvss/exact/rational_piece.hpp"

namespace grpvss::geometry {

using RationalVector = std::array<mpq_class, 3>;

/// Exact copy of a double point.
inline RationalVector to_rational(const Eigen::Vector3d& v) {
  return {mpq_class(v.x()), mpq_class(v.y()), mpq_class(v.z())};
}
inline RationalVector to_rational(const RationalPoint& p) { return {p.x, p.y, p.z}; }

inline RationalVector operator-(const RationalVector& a, const RationalVector& b) {
  return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}
inline mpq_class dot(const RationalVector& a, const RationalVector& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
inline RationalVector cross(const RationalVector& a, const RationalVector& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

/// \brief Exact plane n.x = c through three points, n = (q - p) x (r - p) (not normalized;
/// zero iff the points are collinear). For a counter-clockwise triangle seen from outside,
/// n points outward and the inside is n.x <= c.
struct RationalPlane {
  RationalVector n;
  mpq_class c;
};

inline RationalPlane plane_through(const RationalVector& p, const RationalVector& q,
                                   const RationalVector& r) {
  RationalPlane plane;
  plane.n = cross(q - p, r - p);
  plane.c = dot(plane.n, p);
  return plane;
}

}  // namespace grpvss::geometry

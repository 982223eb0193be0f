#pragma once
/// \file
/// \brief Independent references for the mesh tests, written without any library code:
/// point-in-solid by ray-crossing parity in exact rationals (boost mpq_rational), and
/// uniform random points of a mesh's bounding box.

#include <array>
#include <optional>
#include <random>
#include <stdexcept>
#include <vector>

#include <Eigen/Core>
#include <boost/multiprecision/gmp.hpp>

#include "grpvss/model/triangle_mesh.hpp"

namespace grpvss::testing {

using Rational = boost::multiprecision::mpq_rational;  // GMP-backed: fast enough for thousands of rays
using RVec = std::array<Rational, 3>;

inline RVec rvec(const Eigen::Vector3d& v) { return {Rational(v.x()), Rational(v.y()), Rational(v.z())}; }
inline RVec rsub(const RVec& a, const RVec& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
inline Rational rdot(const RVec& a, const RVec& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
inline RVec rcross(const RVec& a, const RVec& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

/// Crossings of the ray p + t d (t > 0) with the triangles, or nullopt when the ray touches
/// an edge or vertex or lies in a triangle's plane (then another direction is needed).
/// Sets on_surface when p itself lies on a triangle.
inline std::optional<int> ray_crossings(const TriangleMesh& mesh, const RVec& p, const RVec& d,
                                        bool& on_surface) {
  int crossings = 0;
  for (const auto& tri : mesh.triangles) {
    const RVec a = rvec(mesh.vertices[tri[0]]);
    const RVec e1 = rsub(rvec(mesh.vertices[tri[1]]), a);
    const RVec e2 = rsub(rvec(mesh.vertices[tri[2]]), a);
    const RVec n = rcross(e1, e2);
    const RVec s = rsub(p, a);
    if (n[0] == 0 && n[1] == 0 && n[2] == 0) continue;  // degenerate triangle: no area
    const Rational denom = rdot(n, d);
    if (denom == 0) {
      if (rdot(n, s) == 0) return std::nullopt;  // ray in the triangle's plane
      continue;
    }
    const Rational t = -rdot(n, s) / denom;  // p + t d on the plane
    if (t < 0) continue;
    const RVec x{s[0] + t * d[0], s[1] + t * d[1], s[2] + t * d[2]};  // hit point minus a
    // Barycentric sides: signs of n . (e x (x - corner)) for the three edges.
    const Rational u = rdot(n, rcross(e1, x));
    const Rational w = rdot(n, rcross(x, e2));
    const Rational v = rdot(n, n) - u - w;
    if (u < 0 || w < 0 || v < 0) continue;
    if (t == 0) {
      on_surface = true;
      continue;
    }
    if (u == 0 || w == 0 || v == 0) return std::nullopt;  // through an edge or vertex
    ++crossings;
  }
  return crossings;
}

/// Exact: is p in the closed solid bounded by the closed mesh (odd crossing parity, or on a
/// triangle)?
inline bool inside_by_parity(const TriangleMesh& mesh, const Eigen::Vector3d& point) {
  static const std::array<std::array<int, 3>, 4> directions{
      {{1000003, 1414213, 1732051}, {-2236067, 1000033, 2645751}, {3162277, -2449489, 1000037},
       {-1234577, -3000017, 777781}}};
  const RVec p = rvec(point);
  for (const auto& dir : directions) {
    bool on_surface = false;
    const RVec d{Rational(dir[0]), Rational(dir[1]), Rational(dir[2])};
    const auto crossings = ray_crossings(mesh, p, d, on_surface);
    if (on_surface) return true;
    if (crossings) return *crossings % 2 == 1;
  }
  throw std::runtime_error("inside_by_parity: every direction was degenerate");
}

/// Uniform random points of the mesh's bounding box.
inline std::vector<Eigen::Vector3d> random_box_points(const TriangleMesh& mesh, int count,
                                                      std::mt19937_64& rng) {
  Eigen::Vector3d lo = mesh.vertices.front(), hi = lo;
  for (const auto& v : mesh.vertices) {
    lo = lo.cwiseMin(v);
    hi = hi.cwiseMax(v);
  }
  std::vector<Eigen::Vector3d> points;
  for (int i = 0; i < count; ++i) {
    Eigen::Vector3d p;
    for (int k = 0; k < 3; ++k) p[k] = std::uniform_real_distribution<double>(lo[k], hi[k])(rng);
    points.push_back(p);
  }
  return points;
}

}  // namespace grpvss::testing

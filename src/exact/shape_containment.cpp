/// \file
/// \brief Support-function containment checks for boxes, cylinders and spheres, in GMP
/// rationals (every quantity is a polynomial in the input doubles: no rounding anywhere).
/// proof: proofs/shape-containment.md#lemma-support-function

#include "grpvss/exact/shape_containment.hpp"

#include <cmath>
#include <functional>
#include <stdexcept>
#include <string>

#include "grpvss/exact/rational_vector.hpp"

namespace grpvss::geometry {

namespace {

void require_dimension(double value, const char* what) {
  if (!std::isfinite(value) || value < 0.0) {
    throw std::invalid_argument(std::string(what) + " must be finite and >= 0, got " +
                                std::to_string(value));
  }
}

/// Exact plane of face f: its first three loop vertices are never collinear.
RationalPlane face_plane(const ConvexPolytope& p, std::size_t f) {
  const auto& loop = p.faces()[f];
  const auto& v = p.vertices();
  return plane_through(to_rational(v[loop[0]]), to_rational(v[loop[1]]),
                       to_rational(v[loop[2]]));
}

/// True iff every face plane passes `face_holds`.
bool every_face(const ConvexPolytope& p, const std::function<bool(const RationalPlane&)>& holds) {
  for (std::size_t f = 0; f < p.faces().size(); ++f) {
    if (!holds(face_plane(p, f))) return false;
  }
  return true;
}

/// a >= 0 and a^2 >= b (b >= 0): a >= sqrt(b), exactly.
bool at_least_root(const mpq_class& a, const mpq_class& b) { return sgn(a) >= 0 && a * a >= b; }

}  // namespace

// proof: proofs/shape-containment.md#lemma-support-function (h_box(n) = sum |n_i| s_i / 2)
bool box_inside_exactly(const ConvexPolytope& p, const Eigen::Vector3d& size) {
  for (int i = 0; i < 3; ++i) require_dimension(size[i], "box size");
  const RationalVector s = to_rational(size);
  return every_face(p, [&s](const RationalPlane& plane) {
    const mpq_class support = abs(plane.n[0]) * s[0] + abs(plane.n[1]) * s[1] +
                              abs(plane.n[2]) * s[2];
    return support <= 2 * plane.c;
  });
}

// proof: proofs/shape-containment.md#lemma-support-function
// (h_cyl(n) = r |(n_x, n_y)| + |n_z| l / 2)
bool cylinder_inside_exactly(const ConvexPolytope& p, double radius, double length) {
  require_dimension(radius, "cylinder radius");
  require_dimension(length, "cylinder length");
  const mpq_class r(radius), l(length);
  return every_face(p, [&](const RationalPlane& plane) {
    const mpq_class gap = plane.c - abs(plane.n[2]) * l / 2;
    return at_least_root(gap, r * r * (plane.n[0] * plane.n[0] + plane.n[1] * plane.n[1]));
  });
}

// proof: proofs/shape-containment.md#lemma-support-function (h_ball(n) = r |n|)
bool sphere_inside_exactly(const ConvexPolytope& p, double radius) {
  require_dimension(radius, "sphere radius");
  const mpq_class r(radius);
  return every_face(p, [&r](const RationalPlane& plane) {
    return at_least_root(plane.c, r * r * dot(plane.n, plane.n));
  });
}

bool radial_overshoot_at_most(const std::vector<Eigen::Vector3d>& vertices, double radius,
                              double max_relative_overshoot) {
  const mpq_class bound = mpq_class(radius) * (1 + mpq_class(max_relative_overshoot));
  for (const auto& v : vertices) {
    const mpq_class x(v.x()), y(v.y());
    if (x * x + y * y > bound * bound) return false;
  }
  return true;
}

bool spherical_overshoot_at_most(const std::vector<Eigen::Vector3d>& vertices, double radius,
                                 double max_relative_overshoot) {
  const mpq_class bound = mpq_class(radius) * (1 + mpq_class(max_relative_overshoot));
  for (const auto& v : vertices) {
    const RationalVector q = to_rational(v);
    if (dot(q, q) > bound * bound) return false;
  }
  return true;
}

}  // namespace grpvss::geometry

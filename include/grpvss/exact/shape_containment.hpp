#pragma once
/// \file
/// \brief Exact checks that a convex polytope contains a primitive collision shape (a box,
/// a cylinder or a sphere centred at the origin), by comparing the shape's support function
/// with every face plane in rational arithmetic.
/// proof: proofs/shape-containment.md#lemma-support-function
///
/// These are what the shape builders (circumscribed_shapes.hpp) must pass before they return,
/// and what an independent checker can call again on the same vertices.

#include <vector>

#include <Eigen/Core>

#include "grpvss/exact/convex_polytope.hpp"

namespace grpvss::geometry {

/// \brief Exact: is the box [-size/2, size/2] (full side lengths, as URDF's `<box size>`)
/// inside \p p? For every face plane n.x <= c: \f$\sum_i |n_i|\,size_i/2 \le c\f$.
/// \throws std::invalid_argument unless every size is finite and >= 0.
bool box_inside_exactly(const ConvexPolytope& p, const Eigen::Vector3d& size);

/// \brief Exact: is the cylinder {x^2 + y^2 <= r^2, |z| <= length/2} (axis z, centred, as
/// URDF's `<cylinder>`) inside \p p? For every face plane n.x <= c:
/// \f$r\sqrt{n_x^2+n_y^2} + |n_z|\,length/2 \le c\f$, decided by squaring
/// (g = c - |n_z| length/2 >= 0 and g^2 >= r^2 (n_x^2 + n_y^2)). Covers the side and the caps.
/// \throws std::invalid_argument unless radius and length are finite and >= 0.
bool cylinder_inside_exactly(const ConvexPolytope& p, double radius, double length);

/// \brief Exact: is the closed ball B(0, radius) inside \p p? For every face plane:
/// c >= 0 and c^2 >= r^2 |n|^2 (the same test as contains_ball_exactly, restated here in
/// rationals so that a checker need not trust the offset code).
/// \throws std::invalid_argument unless radius is finite and >= 0.
bool sphere_inside_exactly(const ConvexPolytope& p, double radius);

/// \brief Exact: does every vertex v satisfy \f$v_x^2 + v_y^2 \le (1 + \epsilon)^2 r^2\f$
/// (radial overshoot of a circumscribed cylinder at most \f$\epsilon\f$; \f$\epsilon\f$ as a
/// double, taken exactly)?
bool radial_overshoot_at_most(const std::vector<Eigen::Vector3d>& vertices, double radius,
                              double max_relative_overshoot);

/// \brief Exact: does every vertex satisfy \f$|v|^2 \le (1 + \epsilon)^2 r^2\f$ (overshoot of a
/// circumscribed sphere polytope at most \f$\epsilon\f$)?
bool spherical_overshoot_at_most(const std::vector<Eigen::Vector3d>& vertices, double radius,
                                 double max_relative_overshoot);

}  // namespace grpvss::geometry

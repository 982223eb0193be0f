#pragma once
/// \file
/// \brief Primitive collision shapes (URDF `<box>`, `<cylinder>`, `<sphere>`, in the shape's
/// own frame, centred at its origin, cylinder axis z) as convex polytopes that PROVABLY
/// contain them. Each result is the vertex list of an exact hull that has passed the exact
/// support-function check of shape_containment.hpp before it is returned.
/// proof: proofs/shape-containment.md#lemma-support-function
///
/// Overshoot: how far the polytope reaches beyond the true shape, relative to the radius
/// (max over vertices of |v_xy| / r - 1 for the cylinder, |v| / r - 1 for the sphere); it is
/// also checked exactly to be at most the requested maximum. Boxes have none.

#include <vector>

#include <Eigen/Core>

#include "grpvss/exact/shape_limits.hpp"

namespace grpvss::geometry {

/// \brief The 8 corners (+-size_x/2, +-size_y/2, +-size_z/2): the box itself.
/// \throws std::invalid_argument unless every size is finite, > 0 and <= 1e6.
std::vector<Eigen::Vector3d> circumscribed_box(const Eigen::Vector3d& size);

/// \brief Number of sides n (a multiple of 4, >= 4) of the regular polygon whose
/// circumradius exceeds its inradius by at most the given fraction: the smallest n with
/// \f$1/\cos(\pi/n) - 1 \le \epsilon\f$ (with a 1e-6 relative margin for the outward rounding).
/// 1% gives 24, 0.1% gives 72.
/// \throws std::invalid_argument unless 1e-3 <= max_relative_overshoot <= 1.
int cylinder_polygon_sides(double max_relative_overshoot);

/// \brief A prism over a regular n-gon (n = cylinder_polygon_sides()) with vertex angles
/// \f$(2i+1)\pi/n\f$ and z = +-length/2 that contains the cylinder
/// {x^2 + y^2 <= r^2, |z| <= length/2}: every side face at distance >= r from the axis, the
/// caps on the cylinder's end planes, radial overshoot <= max_relative_overshoot — all
/// checked exactly (cylinder_inside_exactly, radial_overshoot_at_most). The polygon is
/// circumscribed about the circle and its vertices are computed at a circumradius inflated
/// by 2^-45 (doubled until the exact check passes): vertices rounded outward.
/// Returns the 2n hull vertices. The polygon is exactly symmetric under x -> -x, y -> -y
/// and x <-> y.
/// \throws std::invalid_argument unless radius and length are finite, > 0, <= 1e6, and
///         1e-3 <= max_relative_overshoot <= 1; std::logic_error if no candidate verifies.
/// Kept per process by its arguments (the result is a function of them alone).
std::vector<Eigen::Vector3d> circumscribed_cylinder(
    double radius, double length, double max_relative_overshoot = kDefaultRelativeOvershoot);
/// circumscribed_cylinder() built and checked now (not kept); the same arguments are required.
std::vector<Eigen::Vector3d> build_circumscribed_cylinder(double radius, double length,
                                                          double max_relative_overshoot);

/// \brief Subdivision frequency of the geodesic icosphere used for a sphere: the smallest
/// \f$\nu\f$ whose subdivided, projected icosahedron (10 nu^2 + 2 vertices) has every
/// triangle plane at distance >= 1 / (1 + epsilon) from the centre (estimate in double; the
/// built polytope is checked exactly). 1% gives 6 (362 vertices), 0.1% gives 18.
/// \throws std::invalid_argument unless 1e-3 <= max_relative_overshoot <= 1.
int sphere_subdivision_frequency(double max_relative_overshoot);

/// \brief A geodesic icosphere (frequency sphere_subdivision_frequency()) scaled so that
/// every face plane of its exact hull is at distance >= radius from the centre — decided
/// exactly (sphere_inside_exactly) — with overshoot <= max_relative_overshoot (checked
/// exactly, spherical_overshoot_at_most). Returns the hull vertices.
/// \throws as circumscribed_cylinder().
/// Kept per process by its arguments, as circumscribed_cylinder().
std::vector<Eigen::Vector3d> circumscribed_sphere(
    double radius, double max_relative_overshoot = kDefaultRelativeOvershoot);
/// circumscribed_sphere() built and checked now (not kept); the same arguments are required.
std::vector<Eigen::Vector3d> build_circumscribed_sphere(double radius,
                                                        double max_relative_overshoot);

}  // namespace grpvss::geometry

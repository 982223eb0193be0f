#pragma once
/// \file
/// \brief Independent exact references for the geometry tests (CGAL lives only in the .cpp):
/// PMP::do_intersect on Epeck meshes (with bounded-side overlap), an exact LP for interior
/// overlap, Polytope_distance_d over Cartesian<Gmpq>, exact orientation predicates. None of
/// these calls grpvss code.

#include <random>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "grpvss/exact/exact_contact.hpp"

namespace grpvss::testing {

using Points = std::vector<Eigen::Vector3d>;

/// Exact contact class: separated iff !PMP::do_intersect(bounded sides); otherwise overlapping
/// iff the LP  max t  s.t.  n_f . x + t <= c_f  (all hull triangles of both sets), t <= 1,
/// has a positive optimum.
geometry::Contact reference_contact(const Points& a, const Points& b);

/// Exact: dist(conv a, conv b)^2 >= x (x a double), via Polytope_distance_d<Cartesian<Gmpq>>.
bool reference_distance_squared_at_least(const Points& a, const Points& b, double x);

/// Exact comparison of the squared distance that CGAL Polytope_distance_d reports when
/// configured with an inexact pricing type as in cgal-notes.md (Homogeneous<double>, NT =
/// double; ET = Gmpzf here) against the true one (Cartesian<Gmpq>): -1 below, 0 equal, +1
/// above the true value.
int double_nt_distance_squared_vs_exact(const Points& a, const Points& b);

/// Rounded exact distance (for messages and ratios only).
double reference_distance(const Points& a, const Points& b);

/// Closest points (rounded) p in conv a and q in conv b.
void reference_closest_points(const Points& a, const Points& b, Eigen::Vector3d& p,
                              Eigen::Vector3d& q);

/// Exact sign of det(q - p, r - p, s - p) = ((q-p) x (r-p)) . (s-p): +1, 0, -1.
int orientation_sign(const Eigen::Vector3d& p, const Eigen::Vector3d& q,
                     const Eigen::Vector3d& r, const Eigen::Vector3d& s);

/// Exact: is x in the closed convex hull of pts (independent CGAL hull, exact predicates)?
bool point_in_hull_exactly(const Points& pts, const Eigen::Vector3d& x);
/// Exact: how many of xs lie OUTSIDE the closed convex hull of pts (hull built once).
int count_points_outside_hull_exactly(const Points& pts, const Points& xs);

/// Exact: does conv(outer) contain conv(inner) (+) B(0, radius)? Every triangle plane of an
/// independent CGAL hull of outer, decided in Gmpzf by squaring (no filter).
bool reference_contains_ball_sum(const Points& outer, const Points& inner, double radius);
/// The 16-point hulls of data/ibm7545/{robot,environment}.txt (every line with exactly three
/// comma-separated numbers, grouped by 16), in file order: 11 robot hulls then 2 obstacles.
std::vector<Points> ibm7545_hulls();

/// Uniform random rotation (from a normalized Gaussian quaternion).
Eigen::Matrix3d random_rotation(std::mt19937_64& rng);

/// R p + t for every point.
Points transformed(const Points& pts, const Eigen::Matrix3d& R, const Eigen::Vector3d& t);

/// Corners of the axis-aligned box [lo, hi].
Points box(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi);

}  // namespace grpvss::testing

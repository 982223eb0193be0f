#pragma once
/// \file
/// \brief Exact intersection test of two convex hulls given by their points, by linear
/// programming in exact rational arithmetic (GMP rationals through boost::multiprecision).
/// Written for the brute-force oracle (motion_oracle.hpp) as a method independent of the
/// library's exact geometry (CGAL hulls + separating-axis classification in
/// src/geometry/exact): no hull is built, no face or axis is enumerated.
///
/// \f$\mathrm{conv}(A)\cap\mathrm{conv}(B)\neq\emptyset\f$ iff the system
/// \f$\sum_i \lambda_i a_i = \sum_j \mu_j b_j,\ \sum_i\lambda_i = 1,\ \sum_j\mu_j = 1,\
/// \lambda,\mu \ge 0\f$ is feasible. Feasibility is decided by phase 1 of the simplex method
/// (artificial variables, Bland's rule, so it terminates) on the exact rational values of the
/// given doubles. Closed sets: touching counts as intersecting.

#include <vector>

#include <Eigen/Core>

namespace grpvss::test {

/// \brief True iff the convex hulls of `a` and `b` share a point (exactly, for the given
/// double coordinates). \pre both non-empty.
bool hulls_intersect_exact_lp(const std::vector<Eigen::Vector3d>& a,
                              const std::vector<Eigen::Vector3d>& b);

}  // namespace grpvss::test

#pragma once
/// \file
/// \brief GMP-rational references for the exact core's rounding (CGAL lives only in the .cpp):
/// the nearest double with ties toward +infinity, and a segment's crossing with a plane.
/// None of these call grpvss code.

#include <Eigen/Core>

namespace CGAL {
class Gmpq;
}

namespace grpvss::testing {

/// The nearest double to x, ties toward +infinity: q with (q + prev q)/2 <= x < (q + next q)/2.
double reference_round(const CGAL::Gmpq& x);

/// Exact sign of ((f1 - f0) x (f2 - f0)) . (x - f0).
int reference_plane_side(const Eigen::Vector3d& x, const Eigen::Vector3d& f0,
                         const Eigen::Vector3d& f1, const Eigen::Vector3d& f2);

/// The exact crossing of segment pq with the plane through f0, f1, f2 (p and q strictly on
/// opposite sides), each coordinate rounded by reference_round.
Eigen::Vector3d reference_crossing(const Eigen::Vector3d& p, const Eigen::Vector3d& q,
                                   const Eigen::Vector3d& f0, const Eigen::Vector3d& f1,
                                   const Eigen::Vector3d& f2);

}  // namespace grpvss::testing

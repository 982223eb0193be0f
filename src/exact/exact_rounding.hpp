#pragma once
/// \file
/// \brief How the exact core turns its rational interference points into doubles: round to
/// nearest, ties toward +infinity, decided exactly; cheap filters first, exact comparisons
/// only where a filter cannot decide.
/// proof: proofs/interference.md#rounding-the-points

#include <optional>

#include <Eigen/Core>

namespace CGAL {
struct Mpzf;
}

namespace grpvss::geometry {

/// \brief num / den (den > 0) rounded to the nearest double, ties toward +infinity, by
/// exact comparisons with the midpoints between consecutive doubles (the reference).
double round_quotient_by_midpoints(const CGAL::Mpzf& num, const CGAL::Mpzf& den);

/// \brief The same double, usually faster: the residual num - q den of a candidate q is
/// exact and an interval enclosure of residual / den places num / den between the midpoints
/// around q; round_quotient_by_midpoints decides what the enclosure cannot.
double round_quotient_to_nearest(const CGAL::Mpzf& num, const CGAL::Mpzf& den);

/// \brief The point where segment pq crosses the plane through f0, f1, f2, rounded to the
/// nearest double per coordinate, from an extended-precision (64-bit significand) evaluation
/// with an a priori error bound. p and q must lie strictly on opposite sides of the plane
/// (the caller has decided that exactly). Returns std::nullopt when, for some coordinate, the
/// bound does not keep the exact value strictly between two midpoints of consecutive
/// doubles (or the platform's long double has no 64-bit significand): the exact path then
/// decides. Whenever it returns a value, that value is the exact crossing's rounding.
/// proof: proofs/interference.md#crossing-by-error-bound
std::optional<Eigen::Vector3d> crossing_rounded_by_error_bound(const Eigen::Vector3d& p,
                                                               const Eigen::Vector3d& q,
                                                               const Eigen::Vector3d& f0,
                                                               const Eigen::Vector3d& f1,
                                                               const Eigen::Vector3d& f2);

}  // namespace grpvss::geometry

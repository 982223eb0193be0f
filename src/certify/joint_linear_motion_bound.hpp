#pragma once
/// \file
/// \brief A tighter bound on how far any point of a link hull travels when the joints move
/// along a straight line in joint space (the CP model between IK samples): the longest
/// vertex chord plus a third of a bound on the path's curvature term.
///
/// proof: proofs/motion-bound.md#lemma-joint-linear-chord
/// For q(s) = q_k + s dq, s in [0, 1] (any monotone reparametrisation), every point v of hull
/// h of link i travels at most
/// \f[ \ell \le \max_{v \in V_h} \|T_i(q_{k+1})v - T_i(q_k)v\| + P_h/3, \qquad
///     P_h = \sum_{m \le i} w_{mh} |\Delta q_m| \Big( [m\ \mathrm{rev}]\,|\Delta q_m|
///           + 2 \sum_{j < m,\ j\ \mathrm{rev}} |\Delta q_j| \Big) \f]
/// with w_{mh} = R_{mh} for a revolute joint m, 1 for a prismatic one. M_h (motion_bound.hpp)
/// adds every joint's sweep; the chord sees joints that undo each other (a SCARA's roll
/// joint holding the tool's orientation on a line).

#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "grpvss/certify/motion_bound.hpp"

namespace grpvss::certify {

/// \brief P_h for the joint-linear motion from q_from to q_to, rounded upward (every
/// operation, the increments included, under an upward rounding scope).
double hull_curvature_bound(const HullRadiusTable& radii, int link, int hull,
                            const Eigen::VectorXd& q_from, const Eigen::VectorXd& q_to);

/// \brief Upper bound (rounded upward) on max over the vertices `raw_L` of the exact chord
/// |T(q_to) v - T(q_from) v|, from the poses forward kinematics computed at both ends:
/// the computed chord plus 2 placement_error (each placed point is within placement_error
/// of its exact place, proofs/fk-rounding.md#fk-rounding).
double vertex_chord_bound(const std::vector<Eigen::Vector3d>& raw_L,
                          const Eigen::Isometry3d& X_WL_from, const Eigen::Isometry3d& X_WL_to,
                          double placement_error);

/// \brief vertex_chord_bound + hull_curvature_bound / 3, rounded upward: an upper bound on the
/// path length of every point of the hull for the joint-linear motion between the two
/// configurations whose link poses are given.
double joint_linear_motion_bound(const HullRadiusTable& radii, int link, int hull,
                                 const std::vector<Eigen::Vector3d>& raw_L,
                                 const Eigen::VectorXd& q_from, const Eigen::Isometry3d& X_WL_from,
                                 const Eigen::VectorXd& q_to, const Eigen::Isometry3d& X_WL_to,
                                 double placement_error);

}  // namespace grpvss::certify

#pragma once
/// \file
/// \brief A solid of revolution (a stack of frusta) about the axis of
/// joint a+1 that contains a hull of link a. Joint a+1 turns it into itself, so the distance from it to any hull beyond joint a+1 does
/// not change with q_{a+1}: a self pair (a, b) may then be held with joint a+1 frozen
/// (proofs/two-ball-cover.md#revolution-route). Used for hulls that are nearly solids of
/// revolution about that axis (a robot's round base about joint 1).

#include <optional>
#include <vector>

#include <Eigen/Geometry>

namespace grpvss::geometry {

/// \brief The stored axis line of a joint in its parent link's frame L, and how far the exact
/// line may be from it: the exact point is within point_error of point_L and the exact unit
/// direction within direction_error of direction_L (a bound on the stored rotation's error).
struct JointAxisLine_L {
  Eigen::Vector3d point_L = Eigen::Vector3d::Zero();
  Eigen::Vector3d direction_L = Eigen::Vector3d::UnitZ();
  double point_error = 0.0;
  double direction_error = 0.0;
};

/// \brief The axis of a joint whose frame J sits at X_PJ in the parent link frame (its z axis
/// is the joint axis), with the stored transform's rotation and translation error bounds.
JointAxisLine_L joint_axis_line(const Eigen::Isometry3d& X_PJ, double rotation_error,
                                double translation_error);

/// \brief One circle of a solid of revolution: at axial coordinate `axial` along the axis,
/// of radius `radius`.
struct RevolutionRing {
  double axial = 0.0;
  double radius = 0.0;
};

/// \brief The convex hull S of the discs \f$\{p + s_i u + w : w \perp u, |w| \le \rho_i\}\f$
/// in link frame L, about the stored axis (p, u) with u an exact unit vector (a coordinate
/// axis or its negative); rings sorted by strictly increasing axial coordinate. Every point x
/// with s = (x - p).u in [s_1, s_k] and distance from the axis at most the piecewise-linear
/// interpolation F(s) of the rings lies in S.
struct RevolutionSolid {
  Eigen::Vector3d axis_point_L = Eigen::Vector3d::Zero();
  Eigen::Vector3d axis_L = Eigen::Vector3d::UnitZ();
  std::vector<RevolutionRing> rings;
  double largest_radius() const;
  double largest_abs_axial() const;
};

/// How round a hull must be about the axis to get a solid: in each of 64 directions across
/// the axis its support is at least this fraction of the solid's largest radius.
inline constexpr double kRevolutionRoundness = 0.98;

/// \brief The margin \f$\mu = e_h + 2(e_t + 4 e_r \Lambda)\f$ rounded up, by which the
/// solid clears the stored hull: it covers the hull's own point error e_h and the stored
/// axis's errors, for points within \f$\Lambda\f$ (`reach`) of the axis point.
/// proof: proofs/two-ball-cover.md#revolution-solid
double revolution_margin_up(const JointAxisLine_L& axis, double hull_point_error, double reach);

/// \brief The solid about `axis` around the hull's vertices `raw_L`: the upper concave
/// envelope of their (axial, radial) coordinates, dilated by the margin of
/// revolution_margin_up in both coordinates, or nullopt when the axis is not a coordinate axis, the hull is empty
/// or not round about it (kRevolutionRoundness). Floating point only proposes it: the checker
/// verifies the containment exactly (src/checker/revolution_check.cpp).
std::optional<RevolutionSolid> enclosing_revolution_solid(
    const std::vector<Eigen::Vector3d>& raw_L, const JointAxisLine_L& axis, double hull_point_error);

/// \brief An upper bound on the largest |coordinate| of any point of the solid (L frame).
double revolution_solid_extent(const RevolutionSolid& cylinder);

/// \brief An upper bound on \f$\max_{c \in S} n\cdot(\hat R c + \hat t)\f$ for the placement
/// \f$\hat X = (\hat R, \hat t)\f$ in exact arithmetic (the image of C under the computed
/// matrix, no rounding of the image). Sets its own upward rounding scope.
/// proof: proofs/two-ball-cover.md#revolution-solid-support
double placed_solid_support_upper(const RevolutionSolid& cylinder,
                                     const Eigen::Isometry3d& X_WL, const Eigen::Vector3d& n);

}  // namespace grpvss::geometry

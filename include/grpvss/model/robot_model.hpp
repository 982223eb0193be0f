#pragma once
/// \file
/// \brief The immutable robot model: an open chain of joints described by standard DH
/// parameters (thesis Eq. 1-2), joint limits, home, acceleration bounds, and per-link hulls.
///
/// Units inside the library: lengths in the file's unit (inches for the IBM 7545), revolute
/// joint values in RADIANS, prismatic joint values in length units, velocities per second.
/// Degrees exist only at the input/output boundary (io/, report/).

#include <limits>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

#include <Eigen/Geometry>

#include "grpvss/model/hull_points.hpp"

namespace grpvss {

enum class JointType { kRevolute = 0, kPrismatic = 1 };

/// \brief Standard DH parameters of one joint: A_i = Rot_z(theta) Trans_z(d) Trans_x(a) Rot_x(alpha).
/// For a revolute joint `theta` is the variable (this field then holds its constant offset,
/// 0 for files in the thesis format); for a prismatic joint `d` is the variable.
struct DhParameters {
  double theta = 0.0;  ///< radians
  double d = 0.0;
  double a = 0.0;
  double alpha = 0.0;  ///< radians
};

/// \brief A joint placed by general frames instead of DH parameters (URDF chains, and a
/// thesis robot on a cell's base pose): frame i sits in frame i-1 at
/// \f$X_{PJ}\,M(q)\,X_{JC}\f$ with \f$M = \mathrm{Rot}_z(q)\f$ or \f$\mathrm{Trans}_z(q)\f$
/// (kinematics/kinematic_chain.hpp). The stored transforms are within the given bounds of the
/// exact ones the input denotes (proofs/urdf-frames.md#frame-steps).
struct JointFrames {
  Eigen::Isometry3d X_PJ = Eigen::Isometry3d::Identity();
  Eigen::Isometry3d X_JC = Eigen::Isometry3d::Identity();
  double X_PJ_rotation_error = 0.0;     ///< spectral norm of (stored R - exact R)
  double X_PJ_translation_error = 0.0;  ///< |stored t - exact t|_2, length units
  double X_JC_rotation_error = 0.0;
  double X_JC_translation_error = 0.0;
};

struct Joint {
  JointType type = JointType::kRevolute;
  DhParameters dh;  ///< unused when `frames` is set
  /// General frames; when set they replace `dh` everywhere (kinematics, motion-bound radii,
  /// checker). proof: proofs/motion-bound.md#lemma-general-axis-radius
  std::optional<JointFrames> frames;
  std::string name;           ///< URDF joint name; empty for thesis files
  double home = 0.0;          ///< joint value at home (rad or length)
  double minimum = 0.0;       ///< lower joint limit
  double maximum = 0.0;       ///< upper joint limit
  double acceleration = 0.0;  ///< maximum admissible acceleration (> 0), per s^2
  double deceleration = 0.0;  ///< maximum admissible deceleration (> 0, a magnitude), per s^2
  /// Largest |dq/dt| (rad/s or length/s) a joint trajectory may ask of the joint: a URDF
  /// `<limit velocity>`; +infinity (no limit) for thesis files and for a velocity 0 or absent.
  double max_velocity = std::numeric_limits<double>::infinity();
};

/// \brief Link i is rigidly attached to frame i (link 0 is the base, fixed in the world).
struct Link {
  std::string name;               ///< URDF link name of frame i; empty for thesis files
  double thickness = 0.0;         ///< the thesis's D_i (not given for link 0)
  std::vector<HullPoints> hulls;  ///< points in the link frame L_i
};

/// \brief Two robot hulls on chain links at least two apart (link_a < link_b) whose distance is
/// verified along the path (self-collision). proof: proofs/two-ball-cover.md#lemma-relative-motion
struct SelfCollisionPair {
  int link_a = 0;
  int hull_a = 0;  ///< index within link_a's hulls
  int link_b = 0;
  int hull_b = 0;
  friend bool operator<(const SelfCollisionPair& a, const SelfCollisionPair& b) {
    return std::tie(a.link_a, a.hull_a, a.link_b, a.hull_b) <
           std::tie(b.link_a, b.hull_a, b.link_b, b.hull_b);
  }
  friend bool operator==(const SelfCollisionPair& a, const SelfCollisionPair& b) {
    return std::tie(a.link_a, a.hull_a, a.link_b, a.hull_b) ==
           std::tie(b.link_a, b.hull_a, b.link_b, b.hull_b);
  }
};

/// \brief Two links whose contact is not verified, with why: "adjacent" (neighbouring chain
/// links), "SRDF" (its `disable_collisions`), "allowed_contacts" (the cell's).
struct UnverifiedLinkPair {
  std::string first;
  std::string second;
  std::string reason;
};

/// \brief Robot description, never modified by algorithms (Pinocchio's Model/Data split:
/// per-query buffers live in kinematics::Workspace).
struct RobotModel {
  std::string name;
  std::vector<Joint> joints;  ///< joints 1..N stored at index 0..N-1
  std::vector<Link> links;    ///< links 0..N (size N+1)
  /// Bound on |stored hull point - exact point| (Euclidean, length units) for every link hull
  /// point: 0 for thesis files (their points are the model); URDF meshes, primitive shapes
  /// and frame changes round. proof: proofs/cell-geometry.md#lemma-geometry-error
  double hull_point_error = 0.0;
  /// Hull pairs verified for self-collision, sorted and unique. Empty for thesis files and
  /// when a cell turns self-collision off (docs/cell-format.md#self-collision).
  std::vector<SelfCollisionPair> self_collision_pairs;
  /// The link pairs not verified for self-collision (listed in every report).
  std::vector<UnverifiedLinkPair> unverified_link_pairs;

  int joint_count() const { return static_cast<int>(joints.size()); }
};

/// \brief How reports call link `index`: its name when it has one ("forearm_link"), else
/// "link 3".
inline std::string link_label(const RobotModel& robot, int index) {
  const auto i = static_cast<std::size_t>(index);
  if (index >= 0 && i < robot.links.size() && !robot.links[i].name.empty()) {
    return robot.links[i].name;
  }
  return "link " + std::to_string(index);
}

/// \brief How reports call hull `hull` of link `link`: the URDF link that declares it
/// ("forearm_link"; a merged fixed link keeps its own name), else link_label().
inline std::string hull_label(const RobotModel& robot, int link, int hull) {
  const auto l = static_cast<std::size_t>(link);
  const auto h = static_cast<std::size_t>(hull);
  if (link >= 0 && hull >= 0 && l < robot.links.size() && h < robot.links[l].hulls.size() &&
      !robot.links[l].hulls[h].name.empty()) {
    return robot.links[l].hulls[h].name;
  }
  return link_label(robot, link);
}

/// \brief "forearm_link / base_link_inertia": how reports name a self-collision pair.
inline std::string self_pair_label(const RobotModel& robot, const SelfCollisionPair& pair) {
  return hull_label(robot, pair.link_b, pair.hull_b) + " / " +
         hull_label(robot, pair.link_a, pair.hull_a);
}

}  // namespace grpvss

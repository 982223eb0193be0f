#pragma once
/// \file
/// \brief A robot read from a robot description (URDF), reduced to the serial chain GRPVSS
/// verifies: N movable joints from the root link to the tip, N+1 chain links that carry every
/// other URDF link rigidly (fixed joints merged, side branches at set joint values), and the
/// collision elements of each chain link with the path of URDF frames that places them.
///
/// Plain data. The numbers are the doubles nearest to the file's decimals; the "exact" robot
/// is the real-number model of those decimals. kinematics/urdf_chain.hpp turns the paths into
/// transforms with proven error bounds (proofs/urdf-frames.md). Units: SI as URDF has them
/// (metres, radians, seconds). Format and choices: docs/urdf.md.

#include <string>
#include <vector>

#include <Eigen/Core>

#include "grpvss/model/robot_model.hpp"
#include "grpvss/model/triangle_mesh.hpp"

namespace grpvss {

/// \brief A URDF `<origin xyz rpy>`: X = Trans(xyz) Rot_z(yaw) Rot_y(pitch) Rot_x(roll),
/// rpy = (roll, pitch, yaw) in radians about the fixed axes x, y, z.
struct UrdfOrigin {
  Eigen::Vector3d xyz = Eigen::Vector3d::Zero();  ///< metres
  Eigen::Vector3d rpy = Eigen::Vector3d::Zero();  ///< radians
};

/// \brief One rigid step of a path of URDF frames (a path is applied left to right:
/// X_AB = step_1 * step_2 * ...).
struct FrameStep {
  enum class Kind {
    kOrigin,         ///< X = origin (a joint's or a collision element's `<origin>`)
    kInverseOrigin,  ///< X = origin^-1 (a fixed joint walked from its child to its parent)
    kRotation,       ///< X = Rot(axis, value): a side-branch revolute/continuous joint
    kTranslation,    ///< X = Trans(value * axis / |axis|): a side-branch prismatic joint
  };
  Kind kind = Kind::kOrigin;
  UrdfOrigin origin;                                   ///< kOrigin, kInverseOrigin
  Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();     ///< as written (nonzero, not normalised)
  double value = 0.0;        ///< kRotation (rad), kTranslation (m)
  double value_error = 0.0;  ///< bound on |value - exact value| (mimic arithmetic), else 0
  std::string joint;         ///< the URDF joint of the step; empty for a collision origin
};

/// \brief Rigid steps from one frame to another, applied left to right.
using FramePath = std::vector<FrameStep>;

/// \brief A movable joint of the chain (joint i moves chain link i against chain link i-1).
struct ChainJointDescription {
  std::string name;
  JointType type = JointType::kRevolute;  ///< revolute and continuous joints are kRevolute
  bool continuous = false;
  std::string parent_link;  ///< URDF link the joint hangs from
  std::string child_link;   ///< URDF link it moves (the frame of chain link i when i < N)
  /// Chain link i-1's frame to the joint frame at q = 0: the origins of the fixed joints merged
  /// in between, then the joint's own `<origin>`.
  FramePath parent_to_joint;
  Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();  ///< as written (nonzero, not normalised)
  double minimum = 0.0;   ///< rad or m; continuous: -infinity
  double maximum = 0.0;   ///< rad or m; continuous: +infinity
  double velocity = 0.0;  ///< `<limit velocity>` (rad/s or m/s); +infinity without `<limit>`
  double acceleration = 0.0;  ///< rad/s^2 or m/s^2: the default or the caller's value
  double home = 0.0;          ///< 0 clamped into [minimum, maximum]
  int line = 0;               ///< line of the `<joint>` element
};

/// \brief A movable joint off the chain (a finger, a tool axis): rigid at `value`.
struct SideJointDescription {
  std::string name;
  JointType type = JointType::kRevolute;
  bool continuous = false;
  double value = 0.0;        ///< the caller's value, else the mimic rule, else 0 clamped into limits
  double value_error = 0.0;  ///< bound on |value - exact value| (nonzero only for mimic joints)
  double minimum = 0.0;
  double maximum = 0.0;
  std::string mimics;        ///< master joint of a `<mimic>`, empty otherwise
  double multiplier = 1.0;   ///< value = multiplier * master + offset
  double offset = 0.0;
  int carried_by = 0;        ///< index of the chain link whose component holds the joint
  int line = 0;
};

/// \brief The shape of a `<collision>` element.
enum class CollisionShape { kMesh, kBox, kCylinder, kSphere };

/// \brief One `<collision>` element, placed in its chain link's frame by `link_to_collision`.
struct CollisionDescription {
  std::string link;  ///< URDF link that declares it
  std::string name;  ///< its `name` attribute, empty when it has none
  int index = 0;     ///< 0-based position among that link's `<collision>` elements
  int line = 0;      ///< line of the `<collision>` element
  CollisionShape shape = CollisionShape::kBox;
  Eigen::Vector3d box_size = Eigen::Vector3d::Zero();  ///< kBox: edge lengths, centred box
  double radius = 0.0;  ///< kCylinder (about z, centred), kSphere
  double length = 0.0;  ///< kCylinder: along z
  std::string mesh_uri;                                    ///< kMesh: as written
  std::string mesh_file;                                   ///< kMesh: the resolved path
  Eigen::Vector3d mesh_scale = Eigen::Vector3d::Ones();    ///< kMesh: `<mesh scale>`
  /// kMesh: vertices in the collision frame, in metres, the scale applied.
  TriangleMesh mesh;
  /// kMesh: bound on |vertex - exact vertex| (scale and mesh-node arithmetic), metres.
  double mesh_vertex_error = 0.0;
  /// The chain link's frame to the collision frame.
  FramePath link_to_collision;
};

/// \brief Chain link i: rigid in frame i of the chain.
struct ChainLinkDescription {
  /// URDF link whose frame is frame i: the root for i = 0, the child of joint i for
  /// 0 < i < N, the tip for i = N.
  std::string frame;
  std::vector<std::string> urdf_links;  ///< every URDF link it carries, in tree order
  /// frame_paths[k]: frame i to the frame of urdf_links[k] (a weld point, `base`, `flange`).
  std::vector<FramePath> frame_paths;
  std::vector<CollisionDescription> collisions;
};

/// \brief The serial chain of a URDF robot from `root_link` to `tip_link`.
struct RobotDescription {
  std::string name;    ///< `<robot name>`
  std::string source;  ///< the URDF file (messages)
  std::string root_link;
  std::string tip_link;
  std::vector<ChainJointDescription> joints;  ///< joints 1..N at index 0..N-1
  std::vector<ChainLinkDescription> links;    ///< chain links 0..N
  /// The child link of joint N to the tip (fixed joints; empty when the tip is that link).
  FramePath last_child_to_tip;
  std::vector<SideJointDescription> side_joints;

  int joint_count() const { return static_cast<int>(joints.size()); }
};

}  // namespace grpvss

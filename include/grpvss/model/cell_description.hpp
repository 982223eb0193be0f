#pragma once
/// \file
/// \brief A robot cell as a cell file (YAML) describes it: the length unit, the robot (a URDF
/// or a thesis robot file) with its base and tool frames, home and accelerations, the
/// obstacles (boxes, cylinders, spheres, meshes, thesis environment files) with names and
/// poses, and the allowed contacts. Plain data, as read: io/cell_file.hpp fills and validates
/// it, the cell stage (cell/load_cell.hpp) turns it into a RobotModel and an Environment.
/// Format: docs/cell-format.md.
///
/// Units: every length is in the cell's unit (`units`), every angle in radians (as in URDF).
/// File paths are resolved (relative ones against the cell file's folder).

#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

namespace grpvss {

/// \brief The length units a cell file may declare.
enum class LengthUnit { kMetre, kMillimetre, kInch };

/// \brief A rigid pose `X_AB` as written: Trans(xyz) then a rotation, either URDF's
/// Rot_z(yaw) Rot_y(pitch) Rot_x(roll) (rpy, radians about the fixed axes x, y, z) or a unit
/// quaternion (w, x, y, z) (normalised when used, never rounded to rpy).
struct CellPose {
  Eigen::Vector3d xyz = Eigen::Vector3d::Zero();  ///< cell units
  Eigen::Vector3d rpy = Eigen::Vector3d::Zero();  ///< radians; unused when quaternion is set
  std::optional<Eigen::Vector4d> quaternion;      ///< (w, x, y, z), nonzero, as written
  int line = 0;  ///< line of the pose's mapping in the cell file; 0 when not given

  /// True when the pose is exactly the identity (no translation, no rotation).
  bool is_identity() const {
    const bool no_rotation = quaternion ? (*quaternion)[1] == 0.0 && (*quaternion)[2] == 0.0 &&
                                              (*quaternion)[3] == 0.0 && (*quaternion)[0] > 0.0
                                        : rpy.isZero(0.0);
    return no_rotation && xyz.isZero(0.0);
  }
};

/// \brief A number given for one named joint (accelerations).
struct NamedJointValue {
  std::string joint;
  double value = 0.0;
  int line = 0;
};

/// \brief The robot of a cell.
struct CellRobot {
  enum class Source { kThesis, kUrdf };
  Source source = Source::kThesis;
  /// The robot file: a thesis robot file (lengths in the cell's unit, angles in degrees) or
  /// a URDF (SI units), resolved.
  std::string file;
  /// `package_paths` (URDF only), resolved against the cell file's folder, in order.
  std::vector<std::string> package_paths;
  std::string srdf;  ///< SRDF file (URDF only), resolved; empty when not given
  std::string tip;   ///< URDF tip link; empty: the reader's choice (the unique leaf)
  CellPose base;     ///< X_WB: the robot's base (its frame 0) in the cell's world W
  CellPose tool;     ///< X_ET: the tool centre point in the tip (end-effector) frame
  /// Start configuration (rad / cell length units), one value per joint; unset: the robot
  /// file's home.
  std::optional<std::vector<double>> home;
  int home_line = 0;
  /// Acceleration (and deceleration) bound for joints not named in `accelerations`
  /// (rad/s^2, or cell length units/s^2 for prismatic joints); unset: the robot file's.
  std::optional<double> default_acceleration;
  std::vector<NamedJointValue> accelerations;  ///< per joint name
  int line = 0;  ///< line of the `robot` mapping (its first key, or its `{`)
};

/// \brief How a mesh obstacle becomes convex pieces (the exact stage's DecomposeMode).
enum class MeshDecomposition { kHull, kParts, kExact };

/// \brief One named obstacle of a cell.
struct CellObstacle {
  enum class Shape { kBox, kCylinder, kSphere, kMesh, kThesisEnvironment };
  std::string name;
  Shape shape = Shape::kBox;
  Eigen::Vector3d box_size = Eigen::Vector3d::Zero();  ///< kBox: full edge lengths, centred
  double radius = 0.0;  ///< kCylinder (axis z, centred), kSphere (centred)
  double length = 0.0;  ///< kCylinder: along z
  std::string file;     ///< kMesh, kThesisEnvironment: resolved path
  /// kMesh: per-axis factor from the mesh file's numbers to cell units (`scale`, or the
  /// factor of the mesh's `units`).
  Eigen::Vector3d scale = Eigen::Vector3d::Ones();
  /// kMesh: true when every scale component is exactly the intended number (1, a decimal
  /// literal that is a double, e.g. 2 or 0.5, or an exact unit factor such as m -> mm);
  /// false when it is the double nearest to it (0.001, mm -> m): its rounding is then part of
  /// the mesh's vertex error (docs/cell-format.md#units).
  bool scale_is_exact = true;
  /// kMesh: the mesh file's declared unit (`units`), when given instead of `scale`.
  std::optional<LengthUnit> mesh_units;
  MeshDecomposition decompose = MeshDecomposition::kHull;  ///< kMesh
  CellPose pose;  ///< X_WO: the shape's frame in the world
  int line = 0;   ///< line of the obstacle's entry
};

/// \brief Two names (robot links or obstacles) whose contact is allowed.
struct AllowedContact {
  std::string first;
  std::string second;
  int line = 0;
};

/// \brief The thesis step rule's environment constants (Eq. 3-1, 3-2) when given by the cell.
struct ThesisConstants {
  double smallest_angle = 0.0;      ///< radians, 0 < angle < pi
  double smallest_thickness = 0.0;  ///< cell units, > 0
  int line = 0;
};

/// \brief Motion defaults of the cell (the command line overrides them).
struct CellMotion {
  std::optional<double> cp_speed;    ///< cell units per second, > 0
  std::optional<double> cp_spacing;  ///< cell units, > 0
};

/// \brief A cell file as read.
struct CellDescription {
  std::string source;  ///< the cell file, as named by the caller
  /// The declared unit of every length in this description (lengths are kept as written).
  LengthUnit units = LengthUnit::kMetre;
  int units_line = 0;
  /// Metres per cell unit (1, 0.001, 0.0254): the double nearest to the exact ratio.
  double metres_per_unit = 1.0;
  /// True when metres_per_unit is the exact ratio (units m only); otherwise a length x
  /// converted as x * metres_per_unit carries a relative error below 2^-51 (the factor's
  /// rounding and the product's, 2^-53 each), docs/cell-format.md#units.
  bool metres_per_unit_is_exact = true;
  CellRobot robot;
  std::vector<CellObstacle> obstacles;
  std::vector<AllowedContact> allowed_contacts;
  /// `self_collision` (URDF robots): verify the robot's hull pairs two or more chain links
  /// apart (docs/cell-format.md#self-collision); false turns it off.
  bool self_collision = true;
  std::optional<double> tolerance;  ///< default tolerance Delta (cell units), > 0
  int tolerance_line = 0;
  CellMotion motion;
  std::optional<ThesisConstants> thesis_constants;
};

}  // namespace grpvss

#include "cell_robot.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "grpvss/common/input_error.hpp"
#include "grpvss/exact/circumscribed_shapes.hpp"
#include "grpvss/io/robot_file.hpp"
#include "grpvss/io/urdf_file.hpp"
#include "grpvss/kinematics/kinematic_chain.hpp"
#include "grpvss/kinematics/urdf_chain.hpp"
#include "grpvss/common/unit_roundoff.hpp"

namespace grpvss::cell {
namespace {

using kinematics::BoundedFactor;
using kinematics::BoundedPoints;
using kinematics::BoundedProduct;

// A chain joint's frames as the model stores them.
JointFrames frames_of(const kinematics::ChainJoint& joint) {
  JointFrames frames;
  frames.X_PJ = joint.X_PJ;
  frames.X_JC = joint.X_JC;
  frames.X_PJ_rotation_error = joint.X_PJ_error.rotation;
  frames.X_PJ_translation_error = joint.X_PJ_error.translation;
  frames.X_JC_rotation_error = joint.X_JC_error.rotation;
  frames.X_JC_translation_error = joint.X_JC_error.translation;
  return frames;
}

BoundedFactor factor_of(const Eigen::Isometry3d& X, double rotation_error,
                        double translation_error) {
  BoundedFactor factor;
  factor.X = X;
  factor.delta = rotation_error;
  factor.tau = translation_error;
  return factor;
}

// A cylinder or sphere <collision> as the vertices of a polytope that contains it (exact
// check inside), with the rounding of its decimal sizes.
BoundedPoints primitive_points(const CollisionDescription& collision) {
  BoundedPoints points;
  if (collision.shape == CollisionShape::kCylinder) {
    points.points = geometry::circumscribed_cylinder(collision.radius, collision.length);
    points.error = 4 * kUnitRoundoff * (collision.radius + collision.length / 2);
  } else {
    points.points = geometry::circumscribed_sphere(collision.radius);
    points.error = 4 * kUnitRoundoff * collision.radius;
  }
  return points;
}

BoundedPoints collision_points_L(const CollisionDescription& collision) {
  if (collision.shape == CollisionShape::kCylinder || collision.shape == CollisionShape::kSphere) {
    return kinematics::place_in_link_frame(collision, primitive_points(collision));
  }
  return kinematics::collision_points_in_link_frame(collision);
}

Joint model_joint(const ChainJointDescription& joint, const kinematics::ChainJoint& chain_joint) {
  Joint model;
  model.type = joint.type;
  model.name = joint.name;
  model.frames = frames_of(chain_joint);
  model.minimum = joint.minimum;
  model.maximum = joint.maximum;
  model.home = joint.home;
  model.acceleration = joint.acceleration;
  model.deceleration = joint.acceleration;
  // URDF convention: a velocity of 0 (or no <limit>) leaves the joint's speed unlimited.
  if (joint.velocity > 0.0) model.max_velocity = joint.velocity;
  return model;
}

io::UrdfReadOptions urdf_options(const CellDescription& cell, const CellLoadOptions& options) {
  io::UrdfReadOptions urdf;
  urdf.tip = cell.robot.tip;
  urdf.package_paths = options.package_paths;
  urdf.package_paths.insert(urdf.package_paths.end(), cell.robot.package_paths.begin(),
                            cell.robot.package_paths.end());
  urdf.use_ros_package_path = options.use_ros_package_path;
  if (cell.robot.default_acceleration) urdf.default_acceleration = *cell.robot.default_acceleration;
  for (const NamedJointValue& value : cell.robot.accelerations) {
    urdf.accelerations[value.joint] = value.value;
  }
  return urdf;
}

RobotModel urdf_robot(const CellDescription& cell, const CellLoadOptions& options,
                      std::vector<io::InputWarning>& warnings) {
  io::UrdfReadResult read = io::read_urdf_file(cell.robot.file, urdf_options(cell, options));
  warnings.insert(warnings.end(), read.warnings.begin(), read.warnings.end());
  const RobotDescription& description = read.description;
  if (description.joint_count() == 0) {
    throw InputError(cell.robot.file, 0, "a chain with at least one movable joint",
                     "none from " + description.root_link + " to " + description.tip_link);
  }
  const kinematics::KinematicChain chain = kinematics::make_chain(description);
  RobotModel robot;
  robot.name = description.name;
  for (int i = 0; i < description.joint_count(); ++i) {
    robot.joints.push_back(model_joint(description.joints[i], chain.joints[i]));
  }
  for (const ChainLinkDescription& link_description : description.links) {
    Link link;
    link.name = link_description.frame;
    for (const CollisionDescription& collision : link_description.collisions) {
      BoundedPoints points = collision_points_L(collision);
      HullPoints hull;
      hull.points = std::move(points.points);
      hull.source_line = collision.line;
      hull.name = collision.link;
      link.hulls.push_back(std::move(hull));
      robot.hull_point_error = std::max(robot.hull_point_error, points.error);
    }
    robot.links.push_back(std::move(link));
  }
  return robot;
}

// The cell's start configuration replaces the robot file's home.
void apply_home(RobotModel& robot, const CellDescription& cell) {
  if (!cell.robot.home) return;
  const std::vector<double>& home = *cell.robot.home;
  if (static_cast<int>(home.size()) != robot.joint_count()) {
    throw InputError(cell.source, cell.robot.home_line,
                     "home with one value per joint (" + std::to_string(robot.joint_count()) + ")",
                     std::to_string(home.size()) + " values");
  }
  for (int i = 0; i < robot.joint_count(); ++i) {
    Joint& joint = robot.joints[static_cast<std::size_t>(i)];
    if (!(home[i] >= joint.minimum && home[i] <= joint.maximum)) {
      throw InputError(cell.source, cell.robot.home_line,
                       "home values within the joint limits",
                       "joint " + (joint.name.empty() ? std::to_string(i + 1) : joint.name) +
                           " at " + std::to_string(home[i]));
    }
    joint.home = home[i];
  }
}

// Thesis robot files carry their accelerations; the cell may override them.
void apply_accelerations(RobotModel& robot, const CellDescription& cell) {
  if (!cell.robot.accelerations.empty()) {
    throw InputError(cell.source, cell.robot.accelerations.front().line,
                     "per-joint accelerations by name only for URDF robots (thesis joints have "
                     "no names)",
                     cell.robot.accelerations.front().joint);
  }
  if (!cell.robot.default_acceleration) return;
  for (Joint& joint : robot.joints) {
    joint.acceleration = *cell.robot.default_acceleration;
    joint.deceleration = *cell.robot.default_acceleration;
  }
}

void transform_hulls(Link& link, const BoundedProduct& X, double point_error, double& error_out) {
  for (HullPoints& hull : link.hulls) {
    BoundedPoints moved = kinematics::transform_points(X, {hull.points, point_error});
    hull.points = std::move(moved.points);
    error_out = std::max(error_out, moved.error);
  }
}

}  // namespace

void place_base_and_tool(RobotModel& robot, const ScaledPose& base, const ScaledPose& tool) {
  if (base.identity && tool.identity) return;
  const kinematics::KinematicChain chain = kinematics::make_chain(robot);
  const double input_error = robot.hull_point_error;
  double error = input_error;
  if (!base.identity) {
    Joint& first = robot.joints.front();
    JointFrames frames = frames_of(chain.joints.front());
    BoundedProduct X_WJ = base.product();
    X_WJ.multiply(factor_of(frames.X_PJ, frames.X_PJ_rotation_error, frames.X_PJ_translation_error));
    frames.X_PJ = X_WJ.X();
    frames.X_PJ_rotation_error = X_WJ.error().rotation;
    frames.X_PJ_translation_error = X_WJ.error().translation;
    first.frames = frames;
    transform_hulls(robot.links.front(), base.product(), input_error, error);
  }
  if (!tool.identity) {
    Joint& last = robot.joints.back();
    JointFrames frames = last.frames ? *last.frames : frames_of(chain.joints.back());
    BoundedProduct X_JT;
    X_JT.multiply(factor_of(frames.X_JC, frames.X_JC_rotation_error, frames.X_JC_translation_error));
    for (const BoundedFactor& factor : tool.factors) X_JT.multiply(factor);
    frames.X_JC = X_JT.X();
    frames.X_JC_rotation_error = X_JT.error().rotation;
    frames.X_JC_translation_error = X_JT.error().translation;
    last.frames = frames;
    transform_hulls(robot.links.back(), tool.inverse_product(), input_error, error);
  }
  // A scaled base or tool translation moves whole links rigidly by at most its error.
  robot.hull_point_error = error + base.translation_error + tool.translation_error;
}

RobotModel load_cell_robot(const CellDescription& cell, const CellLoadOptions& options,
                           double scale, std::vector<io::InputWarning>& warnings) {
  RobotModel robot = cell.robot.source == CellRobot::Source::kUrdf
                         ? urdf_robot(cell, options, warnings)
                         : io::read_robot_file(cell.robot.file);
  if (cell.robot.source == CellRobot::Source::kThesis) apply_accelerations(robot, cell);
  apply_home(robot, cell);
  place_base_and_tool(robot, scaled_pose(cell.robot.base, scale),
                      scaled_pose(cell.robot.tool, scale));
  return robot;
}

}  // namespace grpvss::cell

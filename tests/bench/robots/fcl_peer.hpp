#pragma once
// The FCL peers of the real-robot benchmarks (docs/performance.md#real-robots-and-fcl), on the
// SAME geometry and the SAME forward kinematics as GRPVSS: every link hull of the RobotModel
// and every obstacle hull of the Environment (vertices and faces of the project's exact
// hull of their points: boxes, (boxes, the circumscribing prisms of cylinders, mesh
// pieces) as an fcl::Convex; link poses from kinematics::forward_kinematics. Obstacles sit
// in FCL's DynamicAABBTree broadphase (as MoveIt's FCL world does); each link hull is
// collided against it and the first contact ends the query (a boolean query, as MoveIt's).
//
// Peers of a trajectory (the verifier's planned motion, motion::Trajectory::joints_at):
// - sampled so that no link hull vertex moves more than `resolution` between samples
//   (Delta/4), measured from the FK of consecutive samples (link origin shift + rotation
//   angle x the hull's largest vertex radius);
// - sampled at 1 degree per step (largest joint change), the MoveIt/RoboDK habit;
// - fcl::continuousCollide with conservative advancement (CCDC_CONSERVATIVE_ADVANCEMENT,
//   screw motion of each link hull between its poses at the segment's two ends), per
//   segment, hull by hull against the obstacles whose boxes the hull's swept box meets.
#include <memory>
#include <vector>

#include <Eigen/Geometry>
#include <fcl/fcl.h>

#include "grpvss/certify/motion_bound.hpp"
#include "grpvss/model/environment.hpp"
#include "grpvss/kinematics/forward_kinematics.hpp"
#include "grpvss/kinematics/kinematic_chain.hpp"
#include "grpvss/motion/trajectory.hpp"

namespace grpvss::bench {

/// What a peer did on one trajectory.
struct PeerResult {
  bool collision = false;
  long configurations = 0;  ///< collision queries (samples), or CA calls for the CCD peer
};

class FclScene {
 public:
  /// Builds the FCL objects from the robot's link hulls and the environment's obstacle hulls
  /// (no RobotCell: no offsets). The robot must outlive the scene.
  FclScene(const RobotModel& robot, const Environment& environment);

  /// FK of q, every link hull posed, collided against the obstacle tree. True on contact.
  bool collides(const Eigen::VectorXd& q);

  /// Samples the trajectory: consecutive samples differ by at most `resolution` (metres) in
  /// any hull vertex (resolution_is_joint_angle = false) or in any joint angle (true, rad).
  /// Stops at the first colliding sample (MoveIt's isPathValid).
  PeerResult sampled(const motion::Trajectory& trajectory, double resolution,
                     bool resolution_is_joint_angle);

  /// Conservative advancement per segment (see the file comment). Stops at the first hit.
  PeerResult conservative_advancement(const motion::Trajectory& trajectory);

 private:
  struct HullObject {
    int link = 0;
    int hull = 0;  ///< index within the link
    double vertex_radius = 0.0;  ///< largest |vertex| in the link frame
    std::shared_ptr<fcl::Convexd> geometry;
    std::unique_ptr<fcl::CollisionObjectd> object;
  };
  void place(const Eigen::VectorXd& q);
  double largest_motion(const std::vector<Eigen::Isometry3d>& a,
                        const std::vector<Eigen::Isometry3d>& b) const;
  bool segment_collides_ca(const Eigen::VectorXd& q0, const Eigen::VectorXd& q1,
                           const Eigen::VectorXd& dq_abs, long& calls);

  certify::HullRadiusTable radii_;
  kinematics::KinematicChain chain_;
  kinematics::Workspace workspace_;
  std::vector<HullObject> hulls_;
  std::vector<std::shared_ptr<fcl::Convexd>> obstacle_geometry_;
  std::vector<std::unique_ptr<fcl::CollisionObjectd>> obstacles_;
  fcl::DynamicAABBTreeCollisionManagerd manager_;
};

}  // namespace grpvss::bench

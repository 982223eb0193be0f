#include "bench/robots/fcl_peer.hpp"

#include <algorithm>
#include <cmath>

#include "grpvss/exact/convex_polytope.hpp"

namespace grpvss::bench {
namespace {

// An fcl::Convex of the exact hull of `points` (faces as FCL's [n, v0 .. vn-1] list).
std::shared_ptr<fcl::Convexd> convex_of(const geometry::ConvexPolytope& hull) {
  auto vertices = std::make_shared<std::vector<fcl::Vector3d>>(hull.vertices().begin(),
                                                               hull.vertices().end());
  auto faces = std::make_shared<std::vector<int>>();
  for (const auto& loop : hull.faces()) {
    faces->push_back(static_cast<int>(loop.size()));
    faces->insert(faces->end(), loop.begin(), loop.end());
  }
  return std::make_shared<fcl::Convexd>(vertices, static_cast<int>(hull.faces().size()), faces);
}

struct QueryData {
  bool hit = false;
};

bool stop_at_first_contact(fcl::CollisionObjectd* a, fcl::CollisionObjectd* b, void* data) {
  auto* query = static_cast<QueryData*>(data);
  fcl::CollisionRequestd request;  // one contact, no contact points: a boolean query
  fcl::CollisionResultd result;
  fcl::collide(a, b, request, result);
  if (result.isCollision()) query->hit = true;
  return query->hit;  // true ends the broadphase traversal
}

double rotation_angle(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b) {
  return Eigen::AngleAxisd(a.linear().transpose() * b.linear()).angle();
}

}  // namespace

FclScene::FclScene(const RobotModel& robot, const Environment& environment)
    : radii_(robot), chain_(kinematics::make_chain(robot)), workspace_(robot) {
  for (int link = 0; link < static_cast<int>(robot.links.size()); ++link) {
    const auto& hulls = robot.links[link].hulls;
    for (int h = 0; h < static_cast<int>(hulls.size()); ++h) {
      HullObject object;
      object.link = link;
      object.hull = h;
      const auto polytope = geometry::ConvexPolytope::from_points(hulls[h].points);
      for (const auto& p : polytope.vertices()) {
        object.vertex_radius = std::max(object.vertex_radius, p.norm());
      }
      object.geometry = convex_of(polytope);
      object.object = std::make_unique<fcl::CollisionObjectd>(object.geometry);
      hulls_.push_back(std::move(object));
    }
  }
  std::vector<fcl::CollisionObjectd*> registered;
  for (const HullPoints& obstacle : environment.obstacles) {
    obstacle_geometry_.push_back(convex_of(geometry::ConvexPolytope::from_points(obstacle.points)));
    obstacles_.push_back(std::make_unique<fcl::CollisionObjectd>(obstacle_geometry_.back()));
    obstacles_.back()->computeAABB();
    registered.push_back(obstacles_.back().get());
  }
  manager_.registerObjects(registered);
  manager_.setup();
}

void FclScene::place(const Eigen::VectorXd& q) {
  kinematics::forward_kinematics(chain_, q, workspace_);
  for (HullObject& hull : hulls_) {
    hull.object->setTransform(workspace_.X_WL[hull.link]);
    hull.object->computeAABB();
  }
}

bool FclScene::collides(const Eigen::VectorXd& q) {
  place(q);
  QueryData query;
  for (HullObject& hull : hulls_) {
    manager_.collide(hull.object.get(), &query, stop_at_first_contact);
    if (query.hit) return true;
  }
  return false;
}

// Bound on how far any hull vertex moved between the link poses a and b.
double FclScene::largest_motion(const std::vector<Eigen::Isometry3d>& a,
                                const std::vector<Eigen::Isometry3d>& b) const {
  double largest = 0.0;
  for (const HullObject& hull : hulls_) {
    const int l = hull.link;
    const double motion = (b[l].translation() - a[l].translation()).norm() +
                          rotation_angle(a[l], b[l]) * hull.vertex_radius;
    largest = std::max(largest, motion);
  }
  return largest;
}

PeerResult FclScene::sampled(const motion::Trajectory& trajectory, double resolution,
                             bool resolution_is_joint_angle) {
  PeerResult out;
  const double duration = trajectory.duration();
  double t = 0.0, dt = duration / 1000.0;
  Eigen::VectorXd q = *trajectory.joints_at(0.0);
  ++out.configurations;
  if ((out.collision = collides(q))) return out;
  std::vector<Eigen::Isometry3d> poses = workspace_.X_WL;
  while (t < duration) {
    const double t1 = std::min(duration, t + dt);
    const Eigen::VectorXd q1 = *trajectory.joints_at(t1);
    double moved = 0.0;
    if (resolution_is_joint_angle) {
      moved = (q1 - q).cwiseAbs().maxCoeff();
    } else {
      kinematics::forward_kinematics(chain_, q1, workspace_);
      moved = largest_motion(poses, workspace_.X_WL);
    }
    const double ratio = 0.9 * resolution / std::max(moved, 1e-12);
    if (moved > resolution && dt > 1e-9) {
      dt *= std::max(ratio, 0.1);  // too far: a shorter step from the same sample
      continue;
    }
    ++out.configurations;
    if ((out.collision = collides(q1))) return out;
    poses = workspace_.X_WL;
    t = t1;
    q = q1;
    dt *= std::min(ratio, 2.0);
  }
  return out;
}

bool FclScene::segment_collides_ca(const Eigen::VectorXd& q0, const Eigen::VectorXd& q1,
                                   const Eigen::VectorXd& dq_abs, long& calls) {
  kinematics::forward_kinematics(chain_, q0, workspace_);
  const std::vector<Eigen::Isometry3d> start = workspace_.X_WL;
  kinematics::forward_kinematics(chain_, q1, workspace_);
  fcl::ContinuousCollisionRequestd request;
  request.ccd_motion_type = fcl::CCDM_SCREW;
  request.ccd_solver_type = fcl::CCDC_CONSERVATIVE_ADVANCEMENT;
  request.gjk_solver_type = fcl::GST_LIBCCD;
  for (HullObject& hull : hulls_) {
    // Every point of the hull stays within the motion bound of its start (joint motion).
    hull.object->setTransform(start[hull.link]);
    hull.object->computeAABB();
    fcl::AABBd swept = hull.object->getAABB();
    const double reach = radii_.hull_motion_bound(hull.link, hull.hull, dq_abs);
    swept.min_ -= Eigen::Vector3d::Constant(reach);
    swept.max_ += Eigen::Vector3d::Constant(reach);
    for (std::size_t o = 0; o < obstacles_.size(); ++o) {
      if (!swept.overlap(obstacles_[o]->getAABB())) continue;
      fcl::ContinuousCollisionResultd result;
      ++calls;
      fcl::continuousCollide(hull.geometry.get(), fcl::Transform3d(start[hull.link]),
                             fcl::Transform3d(workspace_.X_WL[hull.link]),
                             obstacle_geometry_[o].get(), fcl::Transform3d::Identity(),
                             fcl::Transform3d::Identity(), request, result);
      if (result.is_collide) return true;
    }
  }
  return false;
}

PeerResult FclScene::conservative_advancement(const motion::Trajectory& trajectory) {
  PeerResult out;
  for (const motion::SegmentTrajectory& segment : trajectory.segments()) {
    const Eigen::VectorXd dq_abs = (segment.q_end - segment.q_start).cwiseAbs();
    if (segment_collides_ca(segment.q_start, segment.q_end, dq_abs, out.configurations)) {
      out.collision = true;
      return out;
    }
  }
  return out;
}

}  // namespace grpvss::bench

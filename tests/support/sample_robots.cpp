#include "support/sample_robots.hpp"

#include <cmath>

#include "support/angles.hpp"

namespace grpvss::test {
namespace {

Joint revolute(double alpha_deg, double d, double a, double min_deg, double max_deg,
               double acc_deg, double dec_deg) {
  Joint joint;
  joint.type = JointType::kRevolute;
  joint.dh.alpha = deg(alpha_deg);
  joint.dh.d = d;
  joint.dh.a = a;
  joint.minimum = deg(min_deg);
  joint.maximum = deg(max_deg);
  joint.acceleration = deg(acc_deg);
  joint.deceleration = deg(dec_deg);
  return joint;
}

// An axis-aligned box [lo, hi] in the link frame: 8 points spanning 3-D.
HullPoints box(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi) {
  HullPoints hull;
  for (int corner = 0; corner < 8; ++corner) {
    hull.points.emplace_back((corner & 1) ? hi.x() : lo.x(), (corner & 2) ? hi.y() : lo.y(),
                             (corner & 4) ? hi.z() : lo.z());
  }
  return hull;
}

Link link_with(double thickness, HullPoints hull) {
  Link link;
  link.thickness = thickness;
  link.hulls.push_back(std::move(hull));
  return link;
}

}  // namespace

RobotModel make_ibm7545_model() {
  RobotModel model;
  model.name = "IBM 7545";
  model.joints.push_back(revolute(0.0, 25.5, 15.8, 0.0, 200.0, 2.0, 1.8));
  model.joints.push_back(revolute(180.0, 0.0, 9.8, 0.0, 135.0, 2.0, 1.8));
  Joint slide;
  slide.type = JointType::kPrismatic;
  slide.minimum = 0.0;
  slide.maximum = 9.8;
  slide.acceleration = 0.7;
  slide.deceleration = 0.6;
  model.joints.push_back(slide);
  model.joints.push_back(revolute(0.0, 15.05, 0.0, -180.0, 180.0, 2.0, 1.8));
  // Boxes roughly where the thesis's hulls are (each in its own link frame).
  model.links.push_back(link_with(0.0, box({-6.25, -10.5, 0.0}, {6.25, 2.5, 30.5})));
  model.links.push_back(link_with(3.23, box({-17.0, -3.0, -3.0}, {2.0, 3.0, 2.0})));
  model.links.push_back(link_with(4.0, box({-10.5, -2.5, -1.0}, {1.5, 2.5, 3.0})));
  model.links.push_back(link_with(1.0, box({-0.5, -0.5, 0.0}, {0.5, 0.5, 18.0})));
  model.links.push_back(link_with(1.5, box({-0.75, -0.75, -3.0}, {0.75, 0.75, 0.0})));
  return model;
}

RobotModel make_puma560_model() {
  RobotModel model;
  model.name = "PUMA 560 style";
  // alpha, d, a, limits, acc, dec (degrees, inches) as in data/puma560/robot.txt.
  model.joints.push_back(revolute(90.0, 26.45, 0.0, -160.0, 160.0, 60.0, 50.0));
  model.joints.push_back(revolute(0.0, 0.0, 17.0, -45.0, 225.0, 50.0, 40.0));
  model.joints.push_back(revolute(-90.0, 5.9, 0.8, -225.0, 45.0, 60.0, 50.0));
  model.joints.push_back(revolute(90.0, 17.0, 0.0, -110.0, 170.0, 90.0, 80.0));
  model.joints.push_back(revolute(-90.0, 0.0, 0.0, -100.0, 100.0, 90.0, 80.0));
  model.joints.push_back(revolute(0.0, 2.2, 0.0, -266.0, 266.0, 120.0, 100.0));
  model.links.push_back(link_with(0.0, box({-5.0, -5.0, 0.0}, {5.0, 5.0, 20.0})));
  model.links.push_back(link_with(4.0, box({-4.0, -7.0, -4.0}, {4.0, 0.0, 4.0})));
  model.links.push_back(link_with(3.0, box({-19.0, -3.0, 2.0}, {2.0, 3.0, 7.0})));
  model.links.push_back(link_with(2.0, box({-2.0, -2.0, -1.0}, {2.0, 2.0, 14.0})));
  model.links.push_back(link_with(1.5, box({-1.5, -1.5, -1.5}, {1.5, 1.5, 1.5})));
  model.links.push_back(link_with(1.5, box({-1.2, -1.2, -1.2}, {1.2, 1.2, 1.2})));
  model.links.push_back(link_with(1.0, box({-1.0, -1.0, -1.0}, {1.0, 1.0, 0.0})));
  return model;
}

}  // namespace grpvss::test

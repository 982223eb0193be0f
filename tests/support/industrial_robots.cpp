#include "support/industrial_robots.hpp"

#include <cmath>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>
#include <stdexcept>

#include "grpvss/kinematics/forward_kinematics.hpp"
#include "support/angles.hpp"

namespace grpvss::test {
namespace {

// One <joint> element of the URDF: only what a serial chain needs.
struct UrdfJoint {
  std::string type, parent, child;
  Eigen::Vector3d xyz = Eigen::Vector3d::Zero(), rpy = Eigen::Vector3d::Zero();
  Eigen::Vector3d axis = Eigen::Vector3d::UnitX();
  double lower = 0.0, upper = 0.0;
};

Eigen::Vector3d three_numbers(const std::string& text) {
  std::istringstream in(text);
  Eigen::Vector3d v;
  in >> v.x() >> v.y() >> v.z();
  return v;
}

std::string attribute(const std::string& element, const std::string& name) {
  std::smatch m;
  if (!std::regex_search(element, m, std::regex(name + "=\"([^\"]*)\""))) return "";
  return m[1];
}

std::string tag(const std::string& body, const std::string& name) {
  std::smatch m;
  if (!std::regex_search(body, m, std::regex("<" + name + "\\b[^>]*>"))) return "";
  return m[0];
}

// child link -> the joint that carries it.
std::map<std::string, UrdfJoint> read_joints(const std::string& file) {
  std::ifstream in(file);
  if (!in) throw std::runtime_error("cannot open " + file);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::map<std::string, UrdfJoint> by_child;
  const std::regex element("<joint name=\"[^\"]*\" type=\"([^\"]*)\">([\\s\\S]*?)</joint>");
  for (std::sregex_iterator it(text.begin(), text.end(), element), end; it != end; ++it) {
    UrdfJoint joint;
    joint.type = (*it)[1];
    const std::string body = (*it)[2];
    joint.parent = attribute(tag(body, "parent"), "link");
    joint.child = attribute(tag(body, "child"), "link");
    const std::string origin = tag(body, "origin");
    if (!attribute(origin, "xyz").empty()) joint.xyz = three_numbers(attribute(origin, "xyz"));
    if (!attribute(origin, "rpy").empty()) joint.rpy = three_numbers(attribute(origin, "rpy"));
    if (!tag(body, "axis").empty()) joint.axis = three_numbers(attribute(tag(body, "axis"), "xyz"));
    if (!tag(body, "limit").empty()) {
      joint.lower = std::stod(attribute(tag(body, "limit"), "lower"));
      joint.upper = std::stod(attribute(tag(body, "limit"), "upper"));
    }
    by_child[joint.child] = joint;
  }
  return by_child;
}

kinematics::KinematicChain chain_between(const std::map<std::string, UrdfJoint>& by_child,
                                         const std::string& root, const std::string& tip) {
  std::vector<UrdfJoint> path;
  for (std::string link = tip; link != root; link = path.back().parent) path.push_back(by_child.at(link));
  kinematics::KinematicChain chain;
  Eigen::Isometry3d pending = Eigen::Isometry3d::Identity();  // fixed joints not yet placed
  for (auto it = path.rbegin(); it != path.rend(); ++it) {
    if (it->type == "fixed") {
      pending = pending * urdf_origin(it->xyz, it->rpy);
      continue;
    }
    kinematics::ChainJoint joint = urdf_revolute(it->xyz, it->rpy, it->axis, it->lower, it->upper);
    joint.X_PJ = pending * joint.X_PJ;
    pending.setIdentity();
    chain.joints.push_back(joint);
  }
  chain.joints.back().X_JC = chain.joints.back().X_JC * pending;
  return chain;
}

kinematics::KinematicChain chain_of(const std::vector<kinematics::ChainJoint>& joints,
                                    const Eigen::Isometry3d& X_6T) {
  kinematics::KinematicChain chain;
  chain.joints = joints;
  chain.joints.back().X_JC = chain.joints.back().X_JC * X_6T;
  return chain;
}

}  // namespace

Eigen::Isometry3d urdf_origin(const Eigen::Vector3d& xyz, const Eigen::Vector3d& rpy) {
  Eigen::Isometry3d X = Eigen::Isometry3d::Identity();
  X.translation() = xyz;
  X.linear() = (Eigen::AngleAxisd(rpy.z(), Eigen::Vector3d::UnitZ()) *
                Eigen::AngleAxisd(rpy.y(), Eigen::Vector3d::UnitY()) *
                Eigen::AngleAxisd(rpy.x(), Eigen::Vector3d::UnitX()))
                   .toRotationMatrix();
  return X;
}

kinematics::ChainJoint urdf_revolute(const Eigen::Vector3d& xyz, const Eigen::Vector3d& rpy,
                                     const Eigen::Vector3d& axis, double lower, double upper) {
  const Eigen::Matrix3d R =
      Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::UnitZ(), axis.normalized()).toRotationMatrix();
  kinematics::ChainJoint joint;
  joint.type = JointType::kRevolute;
  joint.X_PJ = urdf_origin(xyz, rpy);
  joint.X_PJ.linear() = joint.X_PJ.linear() * R;
  joint.X_JC = Eigen::Isometry3d::Identity();
  joint.X_JC.linear() = R.transpose();
  joint.minimum = lower;
  joint.maximum = upper;
  return joint;
}

kinematics::KinematicChain ur5e_chain_from_urdf() {
  return chain_between(read_joints(std::string(GRPVSS_SOURCE_DIR) + "/../shared/robots/ur5e/ur5e.urdf"),
                       "base_link", "tool0");
}

kinematics::KinematicChain kr6_r700_chain() {
  const Eigen::Vector3d none = Eigen::Vector3d::Zero();
  return chain_of({urdf_revolute({0, 0, 0.400}, none, {0, 0, -1}, deg(-170), deg(170)),
                   urdf_revolute({0.025, 0, 0}, none, {0, 1, 0}, deg(-190), deg(45)),
                   urdf_revolute({0.315, 0, 0}, none, {0, 1, 0}, deg(-120), deg(156)),
                   urdf_revolute({0, 0, 0.035}, none, {-1, 0, 0}, deg(-185), deg(185)),
                   urdf_revolute({0.365, 0, 0}, none, {0, 1, 0}, deg(-120), deg(120)),
                   urdf_revolute({0.080, 0, 0}, none, {-1, 0, 0}, deg(-350), deg(350))},
                  urdf_origin(none, {0, kPi / 2, 0}));
}

kinematics::KinematicChain irb2400_chain() {
  const Eigen::Vector3d none = Eigen::Vector3d::Zero();
  return chain_of({urdf_revolute({0, 0, 0}, none, {0, 0, 1}, deg(-180), deg(180)),
                   urdf_revolute({0.100, 0, 0.615}, none, {0, 1, 0}, deg(-100), deg(110)),
                   urdf_revolute({0, 0, 0.705}, none, {0, 1, 0}, deg(-60), deg(65)),
                   urdf_revolute({0, 0, 0.135}, none, {1, 0, 0}, deg(-200), deg(200)),
                   urdf_revolute({0.755, 0, 0}, none, {0, 1, 0}, deg(-120), deg(120)),
                   urdf_revolute({0.085, 0, 0}, none, {1, 0, 0}, deg(-400), deg(400))},
                  urdf_origin(none, {0, kPi / 2, 0}));
}

RobotModel ur5e_dh_model() {
  RobotModel model;
  model.name = "UR5e (DH)";
  const double alpha[6] = {kPi / 2, 0, 0, kPi / 2, -kPi / 2, 0};
  const double a[6] = {0, -0.425, -0.3922, 0, 0, 0};
  const double d[6] = {0.1625, 0, 0, 0.1333, 0.0997, 0.0996};
  for (int i = 0; i < 6; ++i) {
    Joint joint;
    joint.dh = {0.0, d[i], a[i], alpha[i]};
    joint.minimum = i == 2 ? -kPi : -2 * kPi;
    joint.maximum = i == 2 ? kPi : 2 * kPi;
    joint.acceleration = joint.deceleration = 1.0;
    model.joints.push_back(joint);
  }
  model.links.resize(7);
  return model;
}

Eigen::VectorXd random_chain_configuration(const kinematics::KinematicChain& chain,
                                           std::mt19937_64& generator) {
  Eigen::VectorXd q(chain.joint_count());
  for (int i = 0; i < chain.joint_count(); ++i) {
    const kinematics::ChainJoint& joint = chain.joints[static_cast<std::size_t>(i)];
    q[i] = std::uniform_real_distribution<double>(joint.minimum, joint.maximum)(generator);
  }
  return q;
}

Eigen::Isometry3d chain_tool_pose(const kinematics::KinematicChain& chain, const Eigen::VectorXd& q,
                                  const Eigen::Isometry3d& X_ET) {
  return kinematics::end_effector_pose(chain, q) * X_ET;
}

}  // namespace grpvss::test

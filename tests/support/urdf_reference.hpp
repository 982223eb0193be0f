#pragma once
/// \file
/// \brief An independent URDF model for tests: read with tinyxml2 alone (no urdfdom, no
/// src/io), numbers kept as the file's decimal strings, and forward kinematics written from the
/// URDF rules (child = parent * Trans(xyz) * RPY(rpy) * Rot(axis, q) or Trans(q axis/|axis|))
/// in any scalar type: long double, or boost::multiprecision for an exact-ish reference.
/// It shares no code with src/io or src/kinematics.

#include <cmath>
#include <map>
#include <string>
#include <vector>

#include <Eigen/Core>

namespace grpvss::test {

struct ReferenceJoint {
  std::string name;
  std::string type;  ///< "revolute", "continuous", "prismatic", "fixed", ...
  std::string parent;
  std::string child;
  std::string xyz = "0 0 0";
  std::string rpy = "0 0 0";
  std::string axis = "1 0 0";
  double lower = 0.0;
  double upper = 0.0;
  std::string mimic;  ///< master joint, empty when none
  std::string multiplier = "1";
  std::string offset = "0";
};

struct ReferenceCollision {
  std::string link;
  int index = 0;
  std::string xyz = "0 0 0";
  std::string rpy = "0 0 0";
  std::string shape;  ///< "box", "cylinder", "sphere", "mesh"
  std::string size;   ///< box
  std::string radius;
  std::string length;
};

struct ReferenceUrdf {
  std::string root;
  std::vector<ReferenceJoint> joints;
  std::map<std::string, std::size_t> joint_to_child;  ///< child link -> index of its joint
  std::map<std::string, std::vector<ReferenceCollision>> collisions;  ///< by link
};

/// Reads `path` with tinyxml2 (joints, collision origins and primitive sizes).
ReferenceUrdf read_reference_urdf(const std::string& path);

/// The three decimals of "x y z" as text.
std::vector<std::string> three_words(const std::string& text);

/// A decimal string in scalar S (strtold for long double and double, S(string) otherwise).
template <typename S>
S decimal(const std::string& text) {
  if constexpr (std::is_floating_point_v<S>) {
    return static_cast<S>(std::strtold(text.c_str(), nullptr));
  } else {
    return S(text);
  }
}

template <typename S>
Eigen::Matrix<S, 3, 1> decimal3(const std::string& text) {
  const std::vector<std::string> w = three_words(text);
  return {decimal<S>(w[0]), decimal<S>(w[1]), decimal<S>(w[2])};
}

template <typename S>
using Pose = Eigen::Matrix<S, 4, 4>;

/// Rot_z(yaw) Rot_y(pitch) Rot_x(roll), written out.
template <typename S>
Eigen::Matrix<S, 3, 3> rpy_matrix(const Eigen::Matrix<S, 3, 1>& rpy) {
  using std::cos;
  using std::sin;
  const S cr = cos(rpy[0]), sr = sin(rpy[0]), cp = cos(rpy[1]), sp = sin(rpy[1]);
  const S cy = cos(rpy[2]), sy = sin(rpy[2]);
  Eigen::Matrix<S, 3, 3> R;
  R << cy * cp, cy * sp * sr - sy * cr, cy * sp * cr + sy * sr,  //
      sy * cp, sy * sp * sr + cy * cr, sy * sp * cr - cy * sr,   //
      -sp, cp * sr, cp * cr;
  return R;
}

/// Trans(xyz) RPY(rpy) from the decimal strings.
template <typename S>
Pose<S> origin_pose(const std::string& xyz, const std::string& rpy) {
  Pose<S> X = Pose<S>::Identity();
  X.template block<3, 3>(0, 0) = rpy_matrix<S>(decimal3<S>(rpy));
  X.template block<3, 1>(0, 3) = decimal3<S>(xyz);
  return X;
}

/// Rodrigues: cos q I + sin q [n]x + (1 - cos q) n n^T, n = axis / |axis|.
template <typename S>
Eigen::Matrix<S, 3, 3> axis_rotation(const Eigen::Matrix<S, 3, 1>& axis, const S& q) {
  using std::cos;
  using std::sin;
  using std::sqrt;
  const Eigen::Matrix<S, 3, 1> n = axis / sqrt(axis.dot(axis));
  Eigen::Matrix<S, 3, 3> cross;
  cross << S(0), -n[2], n[1], n[2], S(0), -n[0], -n[1], n[0], S(0);
  return Eigen::Matrix<S, 3, 3>::Identity() * cos(q) + cross * sin(q) +
         (n * n.transpose()) * (S(1) - cos(q));
}

/// The motion of a joint at value q.
template <typename S>
Pose<S> joint_motion(const ReferenceJoint& joint, const S& q) {
  using std::sqrt;
  Pose<S> X = Pose<S>::Identity();
  const Eigen::Matrix<S, 3, 1> axis = decimal3<S>(joint.axis);
  if (joint.type == "revolute" || joint.type == "continuous") {
    X.template block<3, 3>(0, 0) = axis_rotation<S>(axis, q);
  } else if (joint.type == "prismatic") {
    X.template block<3, 1>(0, 3) = axis / sqrt(axis.dot(axis)) * q;
  }
  return X;
}

/// Values of every movable joint: `set` ones as given, mimic ones from their master, the rest 0.
template <typename S>
std::map<std::string, S> joint_values(const ReferenceUrdf& urdf, const std::map<std::string, S>& set) {
  std::map<std::string, S> values = set;
  for (int pass = 0; pass < 8; ++pass) {
    for (const ReferenceJoint& joint : urdf.joints) {
      if (!joint.mimic.empty() && values.count(joint.mimic) > 0) {
        values[joint.name] = decimal<S>(joint.multiplier) * values.at(joint.mimic) + decimal<S>(joint.offset);
      }
    }
  }
  return values;
}

/// Pose of `link` in the root frame for the joint values (missing movable joints at 0).
template <typename S>
Pose<S> link_pose(const ReferenceUrdf& urdf, const std::string& link,
                  const std::map<std::string, S>& values) {
  const auto it = urdf.joint_to_child.find(link);
  if (it == urdf.joint_to_child.end()) return Pose<S>::Identity();
  const ReferenceJoint& joint = urdf.joints[it->second];
  const auto value = values.find(joint.name);
  const S q = value != values.end() ? value->second : S(0);
  return (link_pose<S>(urdf, joint.parent, values) * origin_pose<S>(joint.xyz, joint.rpy) *
          joint_motion<S>(joint, q))
      .eval();
}

}  // namespace grpvss::test

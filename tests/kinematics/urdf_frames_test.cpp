// Checks of proofs/urdf-frames.md: every stored factor, product and placed point of a URDF
// robot against a 50-digit evaluation of the exact real-number model of the file's decimals
// (support/urdf_reference.hpp, which parses the decimal strings itself).
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include <boost/multiprecision/cpp_bin_float.hpp>
#include <gtest/gtest.h>

#include "grpvss/io/urdf_file.hpp"
#include "grpvss/kinematics/urdf_chain.hpp"
#include "support/data_paths.hpp"
#include "support/urdf_reference.hpp"

namespace grpvss::kinematics {
namespace {

using Float50 = boost::multiprecision::cpp_bin_float_50;
using Matrix3F = Eigen::Matrix<Float50, 3, 3>;
using Vector3F = Eigen::Matrix<Float50, 3, 1>;

using grpvss::test::kSharedRobots;

// A random decimal such as "-2.71828182845904523" (integer part < limit, 1..20 fraction digits).
std::string random_decimal(std::mt19937_64& generator, int limit, bool allow_zero = true) {
  std::uniform_int_distribution<int> digit(0, 9);
  const int integer = std::uniform_int_distribution<int>(0, limit - 1)(generator);
  const int fraction_digits = std::uniform_int_distribution<int>(1, 20)(generator);
  std::string text = std::to_string(integer) + ".";
  for (int k = 0; k < fraction_digits; ++k) text += static_cast<char>('0' + digit(generator));
  if (!allow_zero && text.find_first_not_of("0.") == std::string::npos) text.back() = '7';
  return (generator() & 1 ? "-" : "") + text;
}

std::string random_triple(std::mt19937_64& generator, int limit) {
  return random_decimal(generator, limit) + " " + random_decimal(generator, limit) + " " +
         random_decimal(generator, limit);
}

Eigen::Vector3d doubles(const std::string& triple) {
  const std::vector<std::string> w = test::three_words(triple);
  return {std::strtod(w[0].c_str(), nullptr), std::strtod(w[1].c_str(), nullptr), std::strtod(w[2].c_str(), nullptr)};
}

// Frobenius norm of (stored - exact) >= its spectral norm: checking it against a spectral-norm
// bound is the stronger test.
Float50 frobenius(const Eigen::Matrix3d& stored, const Matrix3F& exact) {
  Float50 sum = 0;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      const Float50 d = Float50(stored(i, j)) - exact(i, j);
      sum += d * d;
    }
  }
  return sqrt(sum);
}

Float50 distance(const Eigen::Vector3d& stored, const Vector3F& exact) {
  Float50 sum = 0;
  for (int i = 0; i < 3; ++i) sum += (Float50(stored[i]) - exact[i]) * (Float50(stored[i]) - exact[i]);
  return sqrt(sum);
}

FrameStep origin_step(const std::string& xyz, const std::string& rpy, bool inverse) {
  FrameStep step;
  step.kind = inverse ? FrameStep::Kind::kInverseOrigin : FrameStep::Kind::kOrigin;
  step.origin.xyz = doubles(xyz);
  step.origin.rpy = doubles(rpy);
  return step;
}

// Exact pose of an origin step (or its inverse).
test::Pose<Float50> exact_origin(const std::string& xyz, const std::string& rpy, bool inverse) {
  test::Pose<Float50> X = test::origin_pose<Float50>(xyz, rpy);
  if (!inverse) return X;
  test::Pose<Float50> Y = test::Pose<Float50>::Identity();
  const Matrix3F Rt = X.block<3, 3>(0, 0).transpose();
  Y.block<3, 3>(0, 0) = Rt;
  Y.block<3, 1>(0, 3) = -(Rt * X.block<3, 1>(0, 3));
  return Y;
}

void expect_within(const BoundedProduct& product, const test::Pose<Float50>& exact, const std::string& what) {
  const FixedTransformError error = product.error();
  EXPECT_LE(frobenius(product.X().linear(), exact.block<3, 3>(0, 0)), Float50(error.rotation)) << what;
  EXPECT_LE(distance(product.X().translation(), exact.block<3, 1>(0, 3)), Float50(error.translation)) << what;
}

// proof: proofs/urdf-frames.md#planar-factors, #decimal-inputs, #frame-steps (origins).
TEST(LemmaUrdfFrames, OriginStepsAreWithinTheirBoundOfTheExactDecimalTransform) {
  std::mt19937_64 generator(101);
  std::vector<std::pair<std::string, std::string>> origins{
      {"0 0 0", "0 0 3.141592653589793"}, {"0 0 0.1625", "1.570796327 0 0"},
      {"0 -0.0997 -2.044881182297852e-11", "1.570796326589793 3.141592653589793 3.141592653589793"},
      {"0 0 0", "-1.5707963267948966 0 6.283185307179586"}, {"0.088 0 0", "0 0 -0.7853981633974483"}};
  for (int k = 0; k < 400; ++k) origins.emplace_back(random_triple(generator, 3), random_triple(generator, 7));
  double worst = 0.0;
  for (const auto& [xyz, rpy] : origins) {
    for (const bool inverse : {false, true}) {
      const BoundedProduct product = compose_frame_path({origin_step(xyz, rpy, inverse)});
      const test::Pose<Float50> exact = exact_origin(xyz, rpy, inverse);
      expect_within(product, exact, xyz + " / " + rpy);
      worst = std::max(worst, static_cast<double>(frobenius(product.X().linear(), exact.block<3, 3>(0, 0))) /
                                  product.error().rotation);
    }
  }
  std::printf("origin steps: worst rotation error / bound = %.3e\n", worst);
  EXPECT_GT(worst, 0.0);
}

// proof: proofs/urdf-frames.md#planar-factors and #decimal-inputs, one stored factor at a time:
// Rot_k of a decimal angle within sqrt(2) (4u + gamma_1 |angle|), Trans of decimals within
// gamma_1 |t|_1 (these are the tight parts; products add rounding on top).
TEST(LemmaUrdfFrames, SingleFactorsOfDecimalsAreWithinTheirDeltaAndTau) {
  std::mt19937_64 generator(111);
  std::vector<std::string> angles{"3.141592653589793", "-3.141592653589793", "1.5707963267948966",
                                  "1.570796327", "6.283185307179586", "0.7853981633974483", "1e-7"};
  for (int k = 0; k < 300; ++k) angles.push_back(random_decimal(generator, 8, false));
  double worst_rotation = 0.0;
  for (const std::string& angle : angles) {
    for (int axis = 0; axis < 3; ++axis) {
      std::string rpy[3] = {"0", "0", "0"};
      rpy[axis] = angle;
      const std::string text = rpy[0] + " " + rpy[1] + " " + rpy[2];
      const std::vector<BoundedFactor> factors = step_factors(origin_step("0 0 0", text, false));
      ASSERT_EQ(factors.size(), 1u) << text;
      const Matrix3F exact = test::rpy_matrix<Float50>(test::decimal3<Float50>(text));
      const Float50 error = frobenius(factors[0].X.linear(), exact);
      EXPECT_LE(error, Float50(factors[0].delta)) << text;
      worst_rotation = std::max(worst_rotation, static_cast<double>(error) / factors[0].delta);
    }
  }
  double worst_translation = 0.0;
  for (int k = 0; k < 300; ++k) {
    const std::string xyz = random_triple(generator, 3);
    const std::vector<BoundedFactor> factors = step_factors(origin_step(xyz, "0 0 0", false));
    if (factors.empty()) continue;
    const Float50 error = distance(factors[0].X.translation(), test::decimal3<Float50>(xyz));
    EXPECT_LE(error, Float50(factors[0].tau)) << xyz;
    worst_translation = std::max(worst_translation, static_cast<double>(error) / factors[0].tau);
  }
  std::printf("single factors: worst rotation error / delta = %.3f, translation error / tau = %.3f\n",
              worst_rotation, worst_translation);
  EXPECT_GT(worst_rotation, 0.05);
  EXPECT_GT(worst_translation, 0.05);
}

// Quarter and half turns written as decimals keep their frames' axes exactly (the residue rule).
TEST(LemmaUrdfFrames, HalfTurnAboutZIsStoredExactly) {
  const BoundedProduct product = compose_frame_path({origin_step("0 0 0", "0 0 3.141592653589793", false)});
  EXPECT_EQ(product.X().matrix(), Eigen::Vector4d(-1, -1, 1, 1).asDiagonal().toDenseMatrix());
}

// R = G Q: Q the polar factor of R^ (Newton iteration), G the turn of Q e_z onto the exact
// unit axis n. The lemma's construction, in 50 digits.
Matrix3F lemma_rotation(const Eigen::Matrix3d& R_hat, const Vector3F& n) {
  Matrix3F Q = R_hat.cast<Float50>();
  for (int k = 0; k < 12; ++k) Q = ((Q + Matrix3F(Q.inverse().transpose())) / 2).eval();
  const Vector3F v = Q.col(2);
  const Vector3F w = v.cross(n);
  const Float50 c = v.dot(n);
  Matrix3F W;
  W << Float50(0), -w[2], w[1], w[2], Float50(0), -w[0], -w[1], w[0], Float50(0);
  const Matrix3F G = Matrix3F::Identity() + W + (W * W) / (Float50(1) + c);
  return G * Q;
}

// proof: proofs/urdf-frames.md#axis-frame
TEST(LemmaUrdfFrames, AxisFrameIsWithinItsBoundOfARotationAboutTheExactDecimalAxis) {
  std::mt19937_64 generator(202);
  std::vector<std::string> axes{"0 0 1", "0 -1 0", "1 0 0", "0 0 -7", "1 1 1", "0.6 0.8 0",
                                "1e-7 0 1", "-0.0000001 1 0", "3 -4 12"};
  for (int k = 0; k < 300; ++k) axes.push_back(random_triple(generator, 3));
  double worst = 0.0;
  for (const std::string& text : axes) {
    const Eigen::Vector3d axis = doubles(text);
    if (axis == Eigen::Vector3d::Zero()) continue;
    const AxisFrame frame = axis_frame(axis);
    const Vector3F a = test::decimal3<Float50>(text);
    const Vector3F n = a / sqrt(a.dot(a));
    const Matrix3F R = lemma_rotation(frame.R, n);
    ASSERT_LT(static_cast<double>((R.col(2) - n).norm()), 1e-40) << text;
    ASSERT_LT(static_cast<double>((R.transpose() * R - Matrix3F::Identity()).norm()), 1e-40) << text;
    const Float50 error = frobenius(frame.R, R);
    EXPECT_LE(error, Float50(frame.error)) << text;
    if ((axis.array() == 0).count() == 2) {
      EXPECT_EQ(frame.error, 0.0) << text;
      EXPECT_EQ(error, 0) << text;
    } else {
      worst = std::max(worst, static_cast<double>(error) / frame.error);
    }
  }
  std::printf("axis frames: worst error / bound = %.3e\n", worst);
  EXPECT_GT(worst, 0.0);
}

// Exact pose of a side-joint motion step.
test::Pose<Float50> exact_motion(const std::string& axis, const Float50& value, bool rotation) {
  test::ReferenceJoint joint;
  joint.axis = axis;
  joint.type = rotation ? "revolute" : "prismatic";
  return test::joint_motion<Float50>(joint, value);
}

// proof: proofs/urdf-frames.md#frame-steps: paths of origins, inverse origins and side-joint
// motions compose within their bound (Lemma 1 of fk-rounding.md over the factors).
TEST(LemmaUrdfFrames, MixedPathsAreWithinTheirBound) {
  std::mt19937_64 generator(303);
  for (int trial = 0; trial < 200; ++trial) {
    FramePath path;
    test::Pose<Float50> exact = test::Pose<Float50>::Identity();
    for (int s = 0; s < 6; ++s) {
      const int kind = std::uniform_int_distribution<int>(0, 3)(generator);
      if (kind < 2) {
        const std::string xyz = random_triple(generator, 2), rpy = random_triple(generator, 4);
        path.push_back(origin_step(xyz, rpy, kind == 1));
        exact = (exact * exact_origin(xyz, rpy, kind == 1)).eval();
      } else {
        std::string axis = random_triple(generator, 2);
        if (doubles(axis) == Eigen::Vector3d::Zero()) axis = "0 0 1";
        const double value = std::uniform_real_distribution<double>(-3, 3)(generator);
        FrameStep step;
        step.kind = kind == 2 ? FrameStep::Kind::kRotation : FrameStep::Kind::kTranslation;
        step.axis = doubles(axis);
        step.value = value;
        path.push_back(step);
        exact = (exact * exact_motion(axis, Float50(value), kind == 2)).eval();
      }
    }
    expect_within(compose_frame_path(path), exact, "trial " + std::to_string(trial));
  }
}

// proof: proofs/urdf-frames.md#mimic-value
TEST(LemmaUrdfFrames, MimicValuesAreWithinTheirBoundOfTheExactDecimalRule) {
  std::mt19937_64 generator(404);
  for (int trial = 0; trial < 200; ++trial) {
    const std::string m = random_decimal(generator, 4), o = random_decimal(generator, 2);
    const double master = std::uniform_real_distribution<double>(-1, 1)(generator);
    const std::string text =
        "<robot name=\"r\"><link name=\"b\"/><link name=\"a\"/><link name=\"s\"/><link name=\"t\"/>"
        "<joint name=\"j\" type=\"revolute\"><parent link=\"b\"/><child link=\"a\"/>"
        "<limit lower=\"-1\" upper=\"1\" effort=\"1\" velocity=\"1\"/></joint>"
        "<joint name=\"s1\" type=\"revolute\"><parent link=\"b\"/><child link=\"s\"/>"
        "<limit lower=\"-1\" upper=\"1\" effort=\"1\" velocity=\"1\"/></joint>"
        "<joint name=\"s2\" type=\"continuous\"><parent link=\"b\"/><child link=\"t\"/>"
        "<mimic joint=\"s1\" multiplier=\"" + m + "\" offset=\"" + o + "\"/></joint></robot>";
    io::UrdfReadOptions options;
    options.tip = "a";
    options.use_ros_package_path = false;
    options.side_joint_values["s1"] = master;
    const RobotDescription d = io::parse_urdf(text, "r.urdf", options).description;
    const SideJointDescription& s2 = d.side_joints.at(1);
    const Float50 exact = Float50(m) * Float50(master) + Float50(o);
    EXPECT_LE(abs(Float50(s2.value) - exact), Float50(s2.value_error)) << m << " " << o;
  }
}

// A random URDF joint (general axis) and its chain joint: X_PJ Rot_z(q) X_JC against the exact
// Trans(xyz) RPY(rpy) Rot(axis, q), with the bound Lemma 1 gives for the three stored factors.
// proof: proofs/urdf-frames.md#chain-joints
TEST(LemmaUrdfFrames, ChainJointsWithGeneralAxesAreWithinTheirBounds) {
  std::mt19937_64 generator(505);
  for (int trial = 0; trial < 200; ++trial) {
    const std::string xyz = random_triple(generator, 2), rpy = random_triple(generator, 4);
    std::string axis = random_triple(generator, 2);
    if (doubles(axis) == Eigen::Vector3d::Zero()) axis = "1 0 0";
    const bool revolute = trial % 3 != 0;
    RobotDescription d;
    ChainJointDescription joint;
    joint.type = revolute ? JointType::kRevolute : JointType::kPrismatic;
    joint.parent_to_joint = {origin_step(xyz, rpy, false)};
    joint.axis = doubles(axis);
    joint.minimum = -2;
    joint.maximum = 2;
    d.joints = {joint};
    const KinematicChain chain = make_chain(d);
    const double q = std::uniform_real_distribution<double>(-2, 2)(generator);
    BoundedProduct product;
    product.multiply({chain.joints[0].X_PJ, chain.joints[0].X_PJ_error.rotation, chain.joints[0].X_PJ_error.translation});
    product.multiply({joint_motion(joint.type, q), revolute ? std::sqrt(2.0) * 4 * 0x1p-53 : 0.0, 0.0});
    product.multiply({chain.joints[0].X_JC, chain.joints[0].X_JC_error.rotation, chain.joints[0].X_JC_error.translation});
    const test::Pose<Float50> exact = (test::origin_pose<Float50>(xyz, rpy) * exact_motion(axis, Float50(q), revolute)).eval();
    expect_within(product, exact, xyz + " / " + rpy + " / " + axis);
  }
}

// proof: proofs/urdf-frames.md#collision-points: every collision point of the UR5e and the Panda
// (fingers open 0.02) in its chain link's frame, against the 50-digit URDF robot at q = 0.
TEST(LemmaUrdfFrames, CollisionPointsInLinkFramesAreWithinTheirBounds) {
  struct Case {
    std::string urdf, packages, tip;
  };
  for (const Case& c : {Case{kSharedRobots + "ur5e/ur5e.urdf", kSharedRobots + "ur5e", ""},
                        Case{kSharedRobots + "franka_panda/panda.urdf", kSharedRobots + "franka_panda", "panda_hand_tcp"}}) {
    io::UrdfReadOptions options;
    options.tip = c.tip;
    options.package_paths = {c.packages};
    options.use_ros_package_path = false;
    if (!c.tip.empty()) options.side_joint_values["panda_finger_joint1"] = 0.02;
    const RobotDescription d = io::read_urdf_file(c.urdf, options).description;
    const test::ReferenceUrdf urdf = test::read_reference_urdf(c.urdf);
    std::map<std::string, Float50> set;
    if (!c.tip.empty()) set["panda_finger_joint1"] = Float50(0.02);
    const auto values = test::joint_values<Float50>(urdf, set);
    double worst = 0.0;
    for (const ChainLinkDescription& link : d.links) {
      const test::Pose<Float50> X_WF = test::link_pose<Float50>(urdf, link.frame, values);
      test::Pose<Float50> X_FW = test::Pose<Float50>::Identity();
      X_FW.block<3, 3>(0, 0) = X_WF.block<3, 3>(0, 0).transpose();
      X_FW.block<3, 1>(0, 3) = -(X_WF.block<3, 3>(0, 0).transpose() * X_WF.block<3, 1>(0, 3));
      for (const CollisionDescription& collision : link.collisions) {
        if (collision.shape != CollisionShape::kMesh && collision.shape != CollisionShape::kBox) continue;
        const test::ReferenceCollision& rc = urdf.collisions.at(collision.link).at(static_cast<std::size_t>(collision.index));
        const test::Pose<Float50> X_LC = (X_FW * test::link_pose<Float50>(urdf, collision.link, values) *
                                          test::origin_pose<Float50>(rc.xyz, rc.rpy)).eval();
        const BoundedPoints points_C = collision_frame_points(collision);
        const BoundedPoints points_L = place_in_link_frame(collision, points_C);
        const Vector3F half = collision.shape == CollisionShape::kBox ? Vector3F(test::decimal3<Float50>(rc.size) / 2) : Vector3F::Zero();
        for (std::size_t k = 0; k < points_C.points.size(); ++k) {
          Vector3F p = points_C.points[k].cast<Float50>();
          if (collision.shape == CollisionShape::kBox) {  // the exact corner of the decimal size
            for (int i = 0; i < 3; ++i) p[i] = points_C.points[k][i] > 0 ? half[i] : Float50(-half[i]);
          }
          const Vector3F exact = X_LC.block<3, 3>(0, 0) * p + X_LC.block<3, 1>(0, 3);
          const Float50 error = distance(points_L.points[k], exact);
          ASSERT_LE(error, Float50(points_L.error)) << collision.link << " " << collision.index;
          worst = std::max(worst, static_cast<double>(error) / points_L.error);
        }
      }
    }
    std::printf("%s: link-frame points, worst error / bound = %.3e\n", d.name.c_str(), worst);
    EXPECT_GT(worst, 0.0);
  }
}

}  // namespace
}  // namespace grpvss::kinematics

// Recognising OPW and UR arms in chains built the URDF way and from DH, with the parameters,
// signs and offsets the manufacturers' / papers' tables give; and refusing chains that are not.
#include "grpvss/kinematics/family_recognition.hpp"

#include <cmath>

#include <gtest/gtest.h>

#include "support/angles.hpp"
#include "support/industrial_robots.hpp"
#include "support/pose_error.hpp"
#include "support/sample_robots.hpp"

namespace grpvss::kinematics {
namespace {

using grpvss::test::kPi;

void expect_placement(const ModelPlacement& placement, const std::array<double, 6>& sign,
                      const std::array<double, 6>& offset) {
  for (std::size_t i = 0; i < 6; ++i) {
    EXPECT_EQ(placement.sign[i], sign[i]) << "joint " << i + 1;
    EXPECT_NEAR(placement.offset[i], offset[i], 1e-12) << "joint " << i + 1;
  }
}

void expect_identity(const Eigen::Isometry3d& X, double tolerance) {
  EXPECT_LE(X.translation().norm(), tolerance);
  EXPECT_LE(test::rotation_error(X, Eigen::Isometry3d::Identity()), tolerance);
}

void expect_opw(const OpwParameters& p, const OpwParameters& expected, double tolerance) {
  EXPECT_NEAR(p.a1, expected.a1, tolerance);
  EXPECT_NEAR(p.a2, expected.a2, tolerance);
  EXPECT_NEAR(p.b, expected.b, tolerance);
  EXPECT_NEAR(p.c1, expected.c1, tolerance);
  EXPECT_NEAR(p.c2, expected.c2, tolerance);
  EXPECT_NEAR(p.c3, expected.c3, tolerance);
  EXPECT_NEAR(p.c4, expected.c4, tolerance);
}

void expect_ur(const UrParameters& p, const UrParameters& expected, double tolerance) {
  EXPECT_NEAR(p.d1, expected.d1, tolerance);
  EXPECT_NEAR(p.a2, expected.a2, tolerance);
  EXPECT_NEAR(p.a3, expected.a3, tolerance);
  EXPECT_NEAR(p.d4, expected.d4, tolerance);
  EXPECT_NEAR(p.d5, expected.d5, tolerance);
  EXPECT_NEAR(p.d6, expected.d6, tolerance);
}

TEST(FamilyRecognition, Kr6ChainMatchesMoveItsForwardKinematics) {
  // The chain itself against an independent value: opw_kinematics' test quotes MoveIt's FK of
  // the ROS-Industrial KR 6 R700 sixx at q_i = 0.2 (7 digits).
  const Eigen::Isometry3d X = test::chain_tool_pose(test::kr6_r700_chain(), Eigen::VectorXd::Constant(6, 0.2));
  Eigen::Matrix3d R;
  R << -0.5965795, 0.000371195, 0.8025539, -0.2724458, 0.9405218, -0.202958, -0.7548948,
      -0.3397331, -0.5609949;
  EXPECT_LE((X.translation() - Eigen::Vector3d(0.7341169, -0.1520347, 0.182639)).norm(), 1e-6);
  EXPECT_LE((X.linear() - R).cwiseAbs().maxCoeff(), 1e-6);
}

TEST(FamilyRecognition, Kr6IsOpwWithKukasSignsAndOffsets) {
  const Recognition<OpwChainModel> r = recognise_opw(test::kr6_r700_chain());
  ASSERT_TRUE(r.model) << r.reason;
  EXPECT_TRUE(r.reason.empty());
  expect_opw(r.model->parameters, {0.025, -0.035, 0.0, 0.400, 0.315, 0.365, 0.080}, 1e-12);
  // opw_kinematics: sign corrections (-1, 1, 1, -1, 1, -1), offset_2 = -pi/2 in theta = s q - o.
  expect_placement(r.model->placement, {-1, 1, 1, -1, 1, -1}, {0, kPi / 2, 0, 0, 0, 0});
  expect_identity(r.model->placement.X_WB, 1e-12);
  expect_identity(r.model->placement.X_FT, 1e-12);
  EXPECT_LE(r.model->fk_deviation, 1e-14);
}

TEST(FamilyRecognition, Irb2400IsOpwWithThePapersParameters) {
  const Recognition<OpwChainModel> r = recognise_opw(test::irb2400_chain());
  ASSERT_TRUE(r.model) << r.reason;
  expect_opw(r.model->parameters, {0.100, -0.135, 0.0, 0.615, 0.705, 0.755, 0.085}, 1e-12);
  expect_placement(r.model->placement, {1, 1, 1, 1, 1, 1}, {0, 0, kPi / 2, 0, 0, 0});
  expect_identity(r.model->placement.X_WB, 1e-12);
  expect_identity(r.model->placement.X_FT, 1e-12);
}

TEST(FamilyRecognition, Puma560FromDhIsOpwWithAShoulderOffset) {
  // Worked by hand from data/puma560/robot.txt: axis 2 points along -y (joint 2, 3 signs -1),
  // the arm plane sits b = -5.9 beside axis 1, the elbow offset 0.8 is a2; axis 5 along -y.
  const Recognition<OpwChainModel> r = recognise_opw(make_chain(test::make_puma560_model()));
  ASSERT_TRUE(r.model) << r.reason;
  expect_opw(r.model->parameters, {0.0, 0.8, -5.9, 26.45, 17.0, 17.0, 2.2}, 1e-12);
  expect_placement(r.model->placement, {1, -1, -1, 1, -1, 1}, {0, kPi / 2, -kPi / 2, 0, 0, 0});
  expect_identity(r.model->placement.X_WB, 1e-12);
  expect_identity(r.model->placement.X_FT, 1e-12);
}

TEST(FamilyRecognition, Ur5eFromTheUrdfIsUrWithUrsDhTable) {
  const KinematicChain chain = test::ur5e_chain_from_urdf();
  ASSERT_EQ(chain.joint_count(), 6);
  const Recognition<UrChainModel> r = recognise_ur(chain);
  ASSERT_TRUE(r.model) << r.reason;
  // The URDF's angles are 1.570796327 (pi/2 + 2e-10): the fit is within 1e-9, not exact.
  expect_ur(r.model->parameters, {0.1625, -0.425, -0.3922, 0.1333, 0.0997, 0.0996}, 1e-9);
  EXPECT_GT(r.model->fk_deviation, 1e-11);
  EXPECT_LE(r.model->fk_deviation, kFamilyFkTolerance);
  for (std::size_t i = 0; i < 6; ++i) {
    EXPECT_EQ(r.model->placement.sign[i], 1.0);
    EXPECT_NEAR(r.model->placement.offset[i], 0.0, 1e-9);
  }
  // B is the URDF's 'base' frame (base_link turned by pi about z, UR's controller frame), and
  // tool0 is UR's DH flange frame.
  EXPECT_LE(test::rotation_error(r.model->placement.X_WB,
                                 Eigen::Isometry3d(Eigen::AngleAxisd(kPi, Eigen::Vector3d::UnitZ()))),
            1e-9);
  EXPECT_LE(r.model->placement.X_WB.translation().norm(), 1e-12);
  expect_identity(r.model->placement.X_FT, 1e-9);
}

TEST(FamilyRecognition, Ur5eFromDhIsTheSameUr) {
  const Recognition<UrChainModel> r = recognise_ur(make_chain(test::ur5e_dh_model()));
  ASSERT_TRUE(r.model) << r.reason;
  expect_ur(r.model->parameters, {0.1625, -0.425, -0.3922, 0.1333, 0.0997, 0.0996}, 1e-12);
  expect_placement(r.model->placement, {1, 1, 1, 1, 1, 1}, {0, 0, 0, 0, 0, 0});
  expect_identity(r.model->placement.X_WB, 1e-12);
  expect_identity(r.model->placement.X_FT, 1e-12);
  EXPECT_LE(r.model->fk_deviation, 1e-14);
}

// The same robot with every link frame moved by an arbitrary rigid transform G_i and every
// joint frame turned about and slid along its axis: FK of E unchanged up to G_6.
KinematicChain reframed(const KinematicChain& chain, Eigen::Isometry3d& G_6) {
  KinematicChain out = chain;
  Eigen::Isometry3d G_previous = Eigen::Isometry3d::Identity();
  for (std::size_t i = 0; i < out.joints.size(); ++i) {
    const double k = static_cast<double>(i) + 1;
    const Eigen::Isometry3d G = Eigen::Translation3d(0.1 * k, -0.05 * k, 0.02 * k) *
                                Eigen::AngleAxisd(0.3 * k, Eigen::Vector3d(1, 2, 3).normalized());
    const Eigen::Isometry3d slide = Eigen::Translation3d(0, 0, 0.07 * k) *
                                    Eigen::AngleAxisd(0.4 * k, Eigen::Vector3d::UnitZ());
    out.joints[i].X_PJ = G_previous.inverse() * chain.joints[i].X_PJ * slide;
    out.joints[i].X_JC = slide.inverse() * chain.joints[i].X_JC * G;
    G_previous = G;
  }
  G_6 = G_previous;
  return out;
}

TEST(FamilyRecognition, ArbitraryJointFramesGiveTheSameParameters) {
  Eigen::Isometry3d G_6;
  const KinematicChain chain = reframed(test::kr6_r700_chain(), G_6);
  // The tool is given on the moved last frame: X_ET = G_6^-1 puts it back on the flange.
  const Recognition<OpwChainModel> r = recognise_opw(chain, G_6.inverse());
  ASSERT_TRUE(r.model) << r.reason;
  expect_opw(r.model->parameters, {0.025, -0.035, 0.0, 0.400, 0.315, 0.365, 0.080}, 1e-12);
  expect_placement(r.model->placement, {-1, 1, 1, -1, 1, -1}, {0, kPi / 2, 0, 0, 0, 0});
  expect_identity(r.model->placement.X_FT, 1e-12);
  const KinematicChain ur_chain = reframed(test::ur5e_chain_from_urdf(), G_6);
  const Recognition<UrChainModel> ur = recognise_ur(ur_chain, G_6.inverse());
  ASSERT_TRUE(ur.model) << ur.reason;
  expect_ur(ur.model->parameters, {0.1625, -0.425, -0.3922, 0.1333, 0.0997, 0.0996}, 1e-9);
}

TEST(FamilyRecognition, ToolTransformIsCarriedIntoTheFlangeFrame) {
  // A tool 0.2 along the flange axis and 0.05 sideways: c4 takes the axial part, X_FT the rest.
  const Eigen::Isometry3d X_ET = Eigen::Translation3d(0.05, 0, 0.2) *
                                 Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitY());
  const Recognition<OpwChainModel> r = recognise_opw(test::kr6_r700_chain(), X_ET);
  ASSERT_TRUE(r.model) << r.reason;
  EXPECT_NEAR(r.model->parameters.c4, 0.280, 1e-12);
  EXPECT_LE((r.model->placement.X_FT.translation() - Eigen::Vector3d(0.05, 0, 0)).norm(), 1e-12);
  EXPECT_LE(r.model->fk_deviation, 1e-14);
}

TEST(FamilyRecognition, OtherChainsAreRefusedWithTheReason) {
  EXPECT_EQ(recognise_opw(make_chain(test::make_ibm7545_model())).reason,
            "the chain has 4 joints, not 6");
  EXPECT_EQ(recognise_opw(test::ur5e_chain_from_urdf()).reason,
            "axis 4 is not perpendicular to axes 2 and 3");
  EXPECT_EQ(recognise_ur(test::kr6_r700_chain()).reason,
            "axes 1 and 2 do not meet");
  EXPECT_EQ(recognise_ur(make_chain(test::make_puma560_model())).reason,
            "axes 2, 3 and 4 are not parallel");
  // Axis 3 tilted by 1e-3 rad: structure fails.
  KinematicChain tilted = test::kr6_r700_chain();
  tilted.joints[2].X_PJ.linear() = tilted.joints[2].X_PJ.linear() *
                                   Eigen::AngleAxisd(1e-3, Eigen::Vector3d::UnitX()).toRotationMatrix();
  EXPECT_EQ(recognise_opw(tilted).reason, "axes 2 and 3 are not parallel");
}

TEST(FamilyRecognition, ATiltBelowTheStructureToleranceIsCaughtByTheFkCheck) {
  // 3e-8 rad passes the 1e-7 structural checks; the fitted model's FK then differs by ~1e-8.
  KinematicChain tilted = test::kr6_r700_chain();
  tilted.joints[2].X_PJ.linear() = tilted.joints[2].X_PJ.linear() *
                                   Eigen::AngleAxisd(3e-8, Eigen::Vector3d::UnitX()).toRotationMatrix();
  const std::string reason = recognise_opw(tilted).reason;
  EXPECT_NE(reason.find("the fitted OPW model's FK differs from the chain's by"), std::string::npos)
      << reason;
}

}  // namespace
}  // namespace grpvss::kinematics

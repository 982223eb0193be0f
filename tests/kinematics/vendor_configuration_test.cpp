// KUKA Status/Turn and ABB confdata: hand-checked poses, and the geometric bits against the
// chain's own geometry (wrist centre, axes 2 and 3 from FK) at random configurations.
#include "grpvss/kinematics/vendor_configuration.hpp"

#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "grpvss/kinematics/forward_kinematics.hpp"
#include "support/angles.hpp"
#include "support/industrial_robots.hpp"

namespace grpvss::kinematics {
namespace {

using grpvss::test::kPi;
using grpvss::test::deg;

Eigen::VectorXd q_deg(double a1, double a2, double a3, double a4, double a5, double a6) {
  Eigen::VectorXd q(6);
  q << deg(a1), deg(a2), deg(a3), deg(a4), deg(a5), deg(a6);
  return q;
}

OpwChainModel opw_model(const KinematicChain& chain) { return *recognise_opw(chain).model; }

TEST(VendorConfiguration, AbbQuadrantIsTheQuarterTurnCounted) {
  EXPECT_EQ(abb_quadrant(0.0), 0);
  EXPECT_EQ(abb_quadrant(deg(89.9)), 0);
  EXPECT_EQ(abb_quadrant(deg(90.1)), 1);
  EXPECT_EQ(abb_quadrant(deg(180.5)), 2);
  EXPECT_EQ(abb_quadrant(deg(359)), 3);
  EXPECT_EQ(abb_quadrant(deg(-0.1)), -1);
  EXPECT_EQ(abb_quadrant(deg(-90.1)), -2);
  EXPECT_EQ(abb_quadrant(deg(-359)), -4);
}

TEST(VendorConfiguration, KukaStatusAndTurnOfKnownKr6Poses) {
  const OpwChainModel kr6 = opw_model(test::kr6_r700_chain());
  // Upper arm up, forearm level forward: the usual S 'B010'; A2 < 0 sets turn bit 1.
  EXPECT_EQ(kuka_status_turn(kr6, q_deg(0, -90, 90, 0, 45, 0)), (KukaStatusTurn{2, 2}));
  // Forearm tilted back over the shoulder: overhead, wrist behind the lower arm.
  EXPECT_EQ(kuka_status_turn(kr6, q_deg(0, -90, -60, 0, 45, 0)), (KukaStatusTurn{1, 6}));
  // Bit 1 flips at A3 = phi = atan(35 / 365) = 5.4775 deg, the stretched arm of the KR6
  // (its A4 sits 35 mm above A3).
  EXPECT_EQ(kuka_status_turn(kr6, q_deg(0, -90, 5.4, 0, 30, 0)).status, 0);
  EXPECT_EQ(kuka_status_turn(kr6, q_deg(0, -90, 5.5, 0, 30, 0)).status, 2);
  EXPECT_EQ(kuka_status_turn(kr6, q_deg(0, -90, 90, 0, -10, 0)).status, 2 + 4);
  EXPECT_EQ(kuka_status_turn(kr6, q_deg(-10, -90, 30, -5, 20, -100)).turn, 1 + 2 + 8 + 32);
}

TEST(VendorConfiguration, AbbConfdataOfKnownIrb2400Poses) {
  const OpwChainModel irb = opw_model(test::irb2400_chain());
  EXPECT_EQ(abb_confdata(irb, q_deg(0, 0, 0, 0, 30, 0)), (AbbConfdata{0, 0, 0, 0}));
  EXPECT_EQ(abb_confdata(irb, q_deg(0, 0, 0, 0, -30, 0)), (AbbConfdata{0, 0, 0, 1}));
  // Lower arm tilted back 80 deg: wrist centre behind axis 1.
  EXPECT_EQ(abb_confdata(irb, q_deg(100, -80, -50, -120, 30, 200)), (AbbConfdata{1, -2, 2, 4}));
  // Axis 3 at -85 deg (beyond the IRB 2400's -60 deg stop): wrist centre behind the lower arm.
  EXPECT_EQ(abb_confdata(irb, q_deg(0, 0, -85, 0, 30, 0)).cfx, 2);
}

// The two sides measured on the chain: wrist centre (joint 5's frame origin) in the A1 frame
// (world x turned about axis 1 by q1), and in front of the line through axes 2 and 3.
struct ChainSides {
  double ahead_of_axis1;
  double ahead_of_lower_arm;
};

ChainSides chain_sides(const KinematicChain& chain, const Eigen::VectorXd& q) {
  Workspace ws;
  ws.X_WL.assign(7, Eigen::Isometry3d::Identity());
  ws.X_WJ.assign(6, Eigen::Isometry3d::Identity());
  forward_kinematics(chain, q, ws);
  const Eigen::Vector3d forward = Eigen::AngleAxisd(q[0], ws.X_WJ[0].linear().col(2)) * Eigen::Vector3d::UnitX();
  const auto plane = [&](const Eigen::Vector3d& p) { return Eigen::Vector2d(forward.dot(p), p.z()); };
  const Eigen::Vector2d a2 = plane(ws.X_WJ[1].translation());
  const Eigen::Vector2d a3 = plane(ws.X_WJ[2].translation());
  const Eigen::Vector2d wrist = plane(ws.X_WJ[4].translation());
  const Eigen::Vector2d lower = a3 - a2;
  const Eigen::Vector2d front_normal(lower.y(), -lower.x());  // = forward when the arm is up
  return {wrist.x(), front_normal.dot(wrist - a3)};
}

TEST(VendorConfiguration, GeometricBitsAgreeWithTheChainsGeometry) {
  for (const KinematicChain& chain : {test::kr6_r700_chain(), test::irb2400_chain()}) {
    const OpwChainModel model = opw_model(chain);
    std::mt19937_64 generator(9);
    for (int trial = 0; trial < 1000; ++trial) {
      const Eigen::VectorXd q = test::random_chain_configuration(chain, generator);
      const ChainSides sides = chain_sides(chain, q);
      const KukaStatusTurn kuka = kuka_status_turn(model, q);
      const AbbConfdata abb = abb_confdata(model, q);
      EXPECT_EQ((kuka.status & 1) != 0, sides.ahead_of_axis1 < 0);
      EXPECT_EQ((kuka.status & 2) != 0, sides.ahead_of_lower_arm >= 0);
      EXPECT_EQ((kuka.status & 4) != 0, q[4] < 0);
      EXPECT_EQ(abb.cfx, (sides.ahead_of_axis1 < 0 ? 4 : 0) + (sides.ahead_of_lower_arm < 0 ? 2 : 0) +
                             (q[4] < 0 ? 1 : 0));
      EXPECT_EQ(abb.cf1, static_cast<int>(std::floor(q[0] / (kPi / 2))));
    }
  }
}

}  // namespace
}  // namespace grpvss::kinematics

// CpModelCheck::near_singularity (error 8, proofs/cp-joint-path.md#singularity): the position
// Jacobian's smallest singular value below the threshold. The check takes it from the 3 x 3
// J J^T; the reference here is an SVD of the Jacobian, written independently of the check.
#include "certify/cp_model_check.hpp"

#include <cmath>
#include <random>
#include <string>

#include <Eigen/SVD>
#include <gtest/gtest.h>

#include "grpvss/cell/load_cell.hpp"
#include "grpvss/io/environment_file.hpp"
#include "grpvss/io/robot_file.hpp"
#include "grpvss/kinematics/jacobian.hpp"
#include "support/data_paths.hpp"
#include "support/random_configurations.hpp"

namespace grpvss::certify {
namespace {

using test::kSourceDir;

double reference_smallest_singular_value(const RobotCell& cell, const Eigen::VectorXd& q) {
  kinematics::Workspace workspace(cell.robot());
  kinematics::forward_kinematics(cell.chain(), q, workspace);
  const Eigen::MatrixXd jacobian = kinematics::point_jacobian(
      cell.chain(), workspace, cell.robot().joint_count(), Eigen::Vector3d::Zero());
  return Eigen::JacobiSVD<Eigen::MatrixXd>(jacobian).singularValues().minCoeff();
}

// Random configurations, and each one with its joints 2..n swept through a grid so that some
// land near a singularity; the check agrees with the SVD wherever sigma is not within 1e-9
// (relative) of the threshold. Returns how many configurations were near a singularity.
int expect_agreement_with_svd(const RobotCell& cell, double threshold, std::uint64_t seed) {
  CpModelSettings settings;
  settings.singular_value_threshold = threshold;
  CpModelCheck check(cell, settings);
  std::mt19937_64 rng(seed);
  int singular = 0;
  for (int k = 0; k < 400; ++k) {
    const Eigen::VectorXd q = test::random_configuration(cell.robot(), rng);
    const double sigma = reference_smallest_singular_value(cell, q);
    if (std::abs(sigma - threshold) <= 1e-9 * threshold) continue;
    const bool expected = sigma < threshold;
    EXPECT_EQ(check.near_singularity(q), expected) << "configuration " << k << ", sigma " << sigma;
    singular += expected;
  }
  return singular;
}

// Calls visit(cell) with the IBM 7545 in its sample cell (tolerance 0.5 in.); the cell refers
// to the robot and environment, which live here.
template <class Visit>
void with_ibm7545_cell(Visit visit) {
  const RobotModel robot = io::read_robot_file(test::ibm7545_file("robot.txt"));
  const Environment environment = io::read_environment_file(test::ibm7545_file("environment.txt"));
  CellSettings cell_settings;
  cell_settings.tolerance = 0.5;
  visit(RobotCell(robot, environment, cell_settings));
}

TEST(CpSingularity, TheStretchedScaraElbowIsSingularAndTheBentOneIsNot) {
  with_ibm7545_cell([](const RobotCell& cell) {
    const RobotModel& robot = cell.robot();
    CpModelCheck check(cell, CpModelSettings{});
    Eigen::VectorXd q = Eigen::VectorXd::Zero(robot.joint_count());
    q[1] = 0.0;  // elbow straight: the arm's reach direction loses its radial motion
    EXPECT_TRUE(check.near_singularity(q));
    EXPECT_LT(reference_smallest_singular_value(cell, q), 1e-12);
    q[1] = 1e-5;  // sigma ~ 1e-5 x the forearm: still below 1e-3
    EXPECT_TRUE(check.near_singularity(q));
    q[1] = 0.5;
    EXPECT_FALSE(check.near_singularity(q));
    // The vertical joint's column is the unit z: sigma_min is at most 1 (in. per in.).
    EXPECT_NEAR(reference_smallest_singular_value(cell, q), 1.0, 1e-12);
  });
}

TEST(CpSingularity, AgreesWithAnSvdOnRandomConfigurations) {
  with_ibm7545_cell([](const RobotCell& cell) {
    const RobotModel& robot = cell.robot();
    expect_agreement_with_svd(cell, 1e-3, 1);
    // A threshold that random configurations straddle: both answers are exercised.
    EXPECT_GT(expect_agreement_with_svd(cell, 0.2 * reference_smallest_singular_value(
                                                        cell, Eigen::VectorXd::Constant(robot.joint_count(), 0.3)),
                                        2),
              0);
  });
  for (const std::string& file : {kSourceDir + "/tests/data/cells/ur5e-post.yaml",
                                  kSourceDir + "/data/sixaxis/cell.yaml"}) {
    const cell::LoadedCell loaded = cell::load_cell(file);
    CellSettings cell_settings;
    cell_settings.tolerance = loaded.tolerance;
    const RobotCell cell(loaded.robot, loaded.environment, cell_settings);
    expect_agreement_with_svd(cell, 1e-3, 3);
    const int singular = expect_agreement_with_svd(cell, 0.05, 4);
    EXPECT_GT(singular, 0) << file;
    EXPECT_LT(singular, 400) << file;
  }
}

}  // namespace
}  // namespace grpvss::certify

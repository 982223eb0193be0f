#include "grpvss/kinematics/fk_error_bound.hpp"

#include <algorithm>
#include <cstdio>
#include <random>
#include <string>

#include <boost/multiprecision/cpp_bin_float.hpp>
#include <gtest/gtest.h>

#include "grpvss/io/robot_file.hpp"
#include "grpvss/kinematics/forward_kinematics.hpp"
#include "support/kinematics_reference.hpp"
#include "support/random_configurations.hpp"
#include "support/sample_robots.hpp"

namespace grpvss::kinematics {
namespace {

using Float50 = boost::multiprecision::cpp_bin_float_50;

double max_abs_hull_coordinate(const RobotModel& model) {
  double c = 0.0;
  for (const Link& link : model.links) {
    for (const HullPoints& hull : link.hulls) {
      for (const Eigen::Vector3d& p : hull.points) c = std::max(c, p.cwiseAbs().maxCoeff());
    }
  }
  return c;
}

// Checks proofs/fk-rounding.md#fk-rounding: the double FK + hull placement stays within the
// bound of the 50-digit evaluation of the closed-form DH product for the same double inputs.
void check_bound(const RobotModel& model, std::uint64_t seed) {
  const KinematicChain chain = make_chain(model);
  const double bound = forward_kinematics_error_bound(chain, max_abs_hull_coordinate(model));
  Workspace ws(model);
  std::mt19937_64 generator(seed);
  double worst = 0.0;
  for (int trial = 0; trial < 300; ++trial) {
    const Eigen::VectorXd q = test::random_configuration(model, generator);
    forward_kinematics(chain, q, ws);
    place_hull_points(model, ws);
    for (std::size_t link = 0; link < model.links.size(); ++link) {
      const Eigen::Matrix<Float50, 4, 4> X_WL =
          test::reference_link_pose<Float50>(model, q, static_cast<int>(link));
      for (std::size_t h = 0; h < model.links[link].hulls.size(); ++h) {
        const auto& points_L = model.links[link].hulls[h].points;
        for (std::size_t k = 0; k < points_L.size(); ++k) {
          Float50 squared = 0;
          for (int r = 0; r < 3; ++r) {
            Float50 exact = X_WL(r, 3);
            for (int c = 0; c < 3; ++c) exact += X_WL(r, c) * Float50(points_L[k][c]);
            const Float50 difference = Float50(ws.hull_points_W[link][h][k][r]) - exact;
            squared += difference * difference;
          }
          const double error = static_cast<double>(sqrt(squared));
          worst = std::max(worst, error);
          ASSERT_LE(error, bound) << model.name << " link " << link;
        }
      }
    }
  }
  std::printf("%s: FK error bound %.3e, worst measured %.3e\n", model.name.c_str(), bound, worst);
  EXPECT_GT(worst, 0.0);  // the comparison really sees rounding
}

TEST(FkErrorBound, HoldsAgainst50DigitReferenceIbm7545) {
  check_bound(test::make_ibm7545_model(), 41);
}

TEST(FkErrorBound, HoldsAgainst50DigitReferencePuma560) {
  check_bound(test::make_puma560_model(), 42);
}

// The same on the robots as read from data/ (thesis hulls, octagonal prisms).
TEST(FkErrorBound, HoldsOnRobotFiles) {
  for (const char* file : {"data/ibm7545/robot.txt", "data/puma560/robot.txt"}) {
    check_bound(io::read_robot_file(std::string(GRPVSS_SOURCE_DIR) + "/" + file), 43);
  }
}

TEST(FkErrorBound, GrowsWithCoordinatesAndRejectsBadInput) {
  const KinematicChain chain = make_chain(test::make_puma560_model());
  const double small = forward_kinematics_error_bound(chain, 1.0);
  const double large = forward_kinematics_error_bound(chain, 100.0);
  EXPECT_GT(small, 0.0);
  EXPECT_GT(large, small);
  EXPECT_LT(large, 1e-10);  // still far below any tolerance a user would give
  EXPECT_THROW(forward_kinematics_error_bound(chain, -1.0), std::invalid_argument);
}

}  // namespace
}  // namespace grpvss::kinematics

// The thesis's output sample (Appendix A.3) planned end to end with the real readers, the DH
// chain and the IBM 7545 closed-form IK.
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "grpvss/io/path_file.hpp"
#include "grpvss/io/robot_file.hpp"
#include "grpvss/motion/kinematics_adapter.hpp"
#include "grpvss/motion/trajectory.hpp"
#include "grpvss/report/trajectory_report.hpp"
#include "support/data_paths.hpp"


namespace grpvss::motion {
namespace {

using grpvss::test::kIbm7545Data;

struct Sample {
  RobotModel robot = io::read_robot_file(kIbm7545Data + "robot.txt");
  PathProgram program = io::read_path_file(kIbm7545Data + "path-output-sample.txt", robot);
  Trajectory plan(PtpTiming timing) const {
    MotionModel options;
    options.timing = timing;
    return Trajectory::plan(robot, program,
                            make_kinematics_access(robot, select_ik({}, robot, "robot.txt")),
                            options);
  }
};

void expect_joints(const RobotModel& robot, const Eigen::VectorXd& q,
                   std::initializer_list<double> expected) {
  const std::vector<double> shown = report::display_joints(robot, q);
  std::size_t j = 0;
  for (double value : expected) {
    EXPECT_NEAR(shown[j], value, 0.01) << "joint " << j + 1;
    ++j;
  }
}

TEST(Ibm7545Trajectory, OutputSampleSegmentEndsAndError3) {
  const Sample sample;
  const Trajectory trajectory = sample.plan(PtpTiming::kIndependent);
  ASSERT_EQ(trajectory.segments().size(), 3u);
  expect_joints(sample.robot, trajectory.segments()[0].q_end, {61.16, 79.90, 2.45, 171.06});
  expect_joints(sample.robot, trajectory.segments()[1].q_end, {166.68, 75.16, 8.45, -58.16});
  expect_joints(sample.robot, trajectory.segments()[2].q_end, {50, 50, 5, 50});
  ASSERT_EQ(trajectory.errors().size(), 1u);
  EXPECT_EQ(trajectory.errors()[0].code, 3);
  EXPECT_EQ(trajectory.errors()[0].segment, 4);
}

TEST(Ibm7545Trajectory, FirstStepsOfTheOutputSample) {
  const Sample sample;
  const Trajectory trajectory = sample.plan(PtpTiming::kIndependent);
  expect_joints(sample.robot, *trajectory.joints_at(1.025), {1.05, 1.05, 0.24, 1.05});
  expect_joints(sample.robot, *trajectory.joints_at(2.503), {5.26, 5.26, 0.69, 5.26});
  expect_joints(sample.robot, *trajectory.joints_at(3.5), {8.25, 8.25, 0.99, 8.25});
  expect_joints(sample.robot, *trajectory.joints_at(4.483), {11.20, 11.20, 1.28, 11.20});
}

TEST(Ibm7545Trajectory, CpSamplesTraceTheLineAndTheYawRule) {
  const Sample sample;
  const Trajectory trajectory = sample.plan(PtpTiming::kIndependent);
  const SegmentTrajectory& cp = trajectory.segments()[1];
  ASSERT_TRUE(cp.cp);
  const auto forward = make_kinematics_access(sample.robot, select_ik({}, sample.robot, "r")).forward;
  for (std::size_t k = 0; k < cp.cp_samples.size(); ++k) {
    const CpSample& s = cp.cp_samples[k];
    const Eigen::Isometry3d X_WE = forward(s.q);
    const Eigen::Isometry3d X_expected = cp.cp->pose_at(s.l);
    EXPECT_LT((X_WE.translation() - X_expected.translation()).norm(), 1e-9);
    EXPECT_LT((X_WE.linear() - X_expected.linear()).norm(), 1e-9);
    if (k > 0) EXPECT_LE(s.l - cp.cp_samples[k - 1].l, 0.5 + 1e-12);
  }
  EXPECT_EQ(cp.cp_samples.back().l, cp.cp->length());
}

// The CP steps the thesis printed for segment 2 (A.3 steps 35, 36, 40-45, 2 decimals) lie on
// the straight line with the orientation of Eq. 4-18 at their own path length l, and the
// trajectory's IK at that l (nearest the samples) gives the thesis's joints, joint-4 wrap
// included. Checks Eq. 4-17/4-18 and the orientation rule against the thesis's own numbers.
TEST(Ibm7545Trajectory, ThesisCpStepsLieOnTheLineAndMatchOurIk) {
  const Sample sample;
  const Trajectory trajectory = sample.plan(PtpTiming::kIndependent);
  const SegmentTrajectory& cp = trajectory.segments()[1];
  const auto access = make_kinematics_access(sample.robot, select_ik({}, sample.robot, "r"));
  const double steps[8][4] = {{62.69, 95.39, 3.00, -169.16},  {67.36, 107.88, 3.56, -149.23},
                              {112.45, 126.75, 5.77, -74.22}, {125.16, 122.05, 6.32, -63.45},
                              {136.72, 114.01, 6.87, -57.16}, {147.39, 103.13, 7.42, -54.62},
                              {157.66, 89.49, 7.98, -55.22},  {166.68, 75.16, 8.45, -58.16}};
  const Eigen::Vector3d p_s = cp.cp->start_pose().translation();
  const Eigen::Vector3d direction = (cp.cp->end_pose().translation() - p_s).normalized();
  for (const auto& step : steps) {
    Eigen::VectorXd q(4);
    q << step[0] * M_PI / 180, step[1] * M_PI / 180, step[2], step[3] * M_PI / 180;
    const Eigen::Isometry3d X_WE = access.forward(q);
    const double l = (X_WE.translation() - p_s).dot(direction);
    const Eigen::Isometry3d X_line = cp.cp->pose_at(l);
    EXPECT_LT((X_WE.translation() - X_line.translation()).norm(), 0.01) << "l = " << l;
    // Rotation angle between the thesis pose and Eq. 4-18 at l: within the 2-decimal rounding.
    const double angle = Eigen::AngleAxisd(X_WE.linear().transpose() * X_line.linear()).angle();
    EXPECT_LT(angle * 180 / M_PI, 0.02) << "l = " << l;
    const Eigen::VectorXd ours = *trajectory.joints_at(cp.start_time + l);  // cp_speed 1
    const std::vector<double> shown = report::display_joints(sample.robot, ours);
    for (int j = 0; j < 4; ++j) EXPECT_NEAR(shown[j], step[j], 0.02) << "l = " << l << " joint " << j + 1;
  }
}

// Segment 3 (PTP(JCS)) steps of A.3: the time of each step is recovered from joint 1 alone
// (closed form of its trapezoid: a = 2, v = 3, d = 1.8 deg/s^2, deg/s), then the other joints
// must match the thesis: independent per-joint trapezoids in this segment too.
TEST(Ibm7545Trajectory, ThesisPtpJcsStepsOfSegment3) {
  const Sample sample;
  const Trajectory trajectory = sample.plan(PtpTiming::kIndependent);
  const SegmentTrajectory& ptp = trajectory.segments()[2];
  const double start_1 = ptp.q_start[0] * 180 / M_PI;  // 166.68
  const double distance_1 = start_1 - 50.0;
  const double t_f = 1.5 + (distance_1 - 2.25 - 2.5) / 3.0 + 3.0 / 1.8;
  struct Step {
    double t;
    double joints[4];
  };
  const Step steps[] = {
      {std::sqrt(start_1 - 165.16), {165.16, 73.64, 8.14, -56.64}},                   // step 46
      {1.5 + (start_1 - 160.84 - 2.25) / 3.0, {160.84, 69.32, 7.71, -52.32}},         // step 47
      {t_f - std::sqrt(2.0 * (52.34 - 50.0) / 1.8), {52.34, 50.00, 5.00, 50.00}},     // step 82
      {t_f, {50.00, 50.00, 5.00, 50.00}},                                             // step 83
  };
  EXPECT_NEAR(ptp.duration, t_f, 1e-9);
  for (const Step& step : steps) {
    const std::vector<double> shown =
        report::display_joints(sample.robot, *trajectory.joints_at(ptp.start_time + step.t));
    for (int j = 0; j < 4; ++j) EXPECT_NEAR(shown[j], step.joints[j], 0.02) << "t = " << step.t << " joint " << j + 1;
  }
}

TEST(Ibm7545Trajectory, SynchronizedSegmentsEndTogetherAtTheSameJoints) {
  const Sample sample;
  const Trajectory independent = sample.plan(PtpTiming::kIndependent);
  const Trajectory synchronized = sample.plan(PtpTiming::kSynchronized);
  ASSERT_EQ(synchronized.segments().size(), 3u);
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_TRUE(synchronized.segments()[i].q_end.isApprox(independent.segments()[i].q_end, 1e-12));
    EXPECT_DOUBLE_EQ(synchronized.segments()[i].duration, independent.segments()[i].duration);
    if (synchronized.segments()[i].ptp)
      for (const JointMotion& joint : synchronized.segments()[i].ptp->joints())
        if (joint.natural_duration() > 0) EXPECT_EQ(joint.duration(), synchronized.segments()[i].duration);
  }
}

}  // namespace
}  // namespace grpvss::motion

// The chord bound of proofs/motion-bound.md#lemma-joint-linear-chord as implemented
// (src/certify/joint_linear_motion_bound.cpp) and as the checker decides it: hand numbers,
// the CP certificates that rely on it, and the tampering the checker must reject.
#include "certify/joint_linear_motion_bound.hpp"

#include <tuple>

#include <cmath>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "grpvss/evidence/certificate.hpp"
#include "grpvss/checker/certificate_checker.hpp"
#include "grpvss/certify/robot_cell.hpp"
#include "grpvss/kinematics/forward_kinematics.hpp"
#include "certify/step_axis_radius.hpp"
#include "support/ibm7545_run.hpp"
#include "support/sample_robots.hpp"

namespace grpvss::certify {
namespace {

constexpr double kDeg = M_PI / 180.0;

TEST(JointLinearMotionBound, CurvatureBoundFollowsTheFormulaOnTheIbm7545) {
  const RobotModel robot = test::make_ibm7545_model();
  const HullRadiusTable radii(robot);
  Eigen::VectorXd q_from(4), q_to(4);
  q_from << 10 * kDeg, 20 * kDeg, 1.0, -30 * kDeg;
  q_to << 13 * kDeg, 16 * kDeg, 1.5, -26 * kDeg;
  const double d1 = 3 * kDeg, d2 = 4 * kDeg, d3 = 0.5, d4 = 4 * kDeg;
  const int link = 4;
  for (int hull = 0; hull < radii.hull_count(link); ++hull) {
    const double r1 = radii.radius(link, hull, 1), r2 = radii.radius(link, hull, 2);
    const double r4 = radii.radius(link, hull, 4);
    // m = 1: R1 d1 d1; m = 2: R2 d2 (d2 + 2 d1); m = 3 (prismatic): d3 (2 (d1 + d2));
    // m = 4: R4 d4 (d4 + 2 (d1 + d2)).
    const double expected = r1 * d1 * d1 + r2 * d2 * (d2 + 2 * d1) + d3 * 2 * (d1 + d2) +
                            r4 * d4 * (d4 + 2 * (d1 + d2));
    const double bound = hull_curvature_bound(radii, link, hull, q_from, q_to);
    EXPECT_GE(bound, expected * (1.0 - 1e-15));
    EXPECT_NEAR(bound, expected, 1e-13 * expected);
  }
  // Nothing before a link moves it: the base (link 0) has no curvature term.
  EXPECT_EQ(hull_curvature_bound(radii, 0, 0, q_from, q_to), 0.0);
}

TEST(JointLinearMotionBound, VertexChordIsTheLongestVertexDisplacementPlusTwicePlacementError) {
  const std::vector<Eigen::Vector3d> vertices{{0, 0, 0}, {1, 0, 0}, {0, 2, 0}};
  Eigen::Isometry3d from = Eigen::Isometry3d::Identity();
  Eigen::Isometry3d to = Eigen::Isometry3d::Identity();
  to.translation() << 3, 4, 0;
  EXPECT_EQ(vertex_chord_bound(vertices, from, to, 0.0), 5.0);
  EXPECT_GE(vertex_chord_bound(vertices, from, to, 1e-9), 5.0 + 2e-9);
  // A quarter turn about z: (0, 2, 0) moves by 2 sqrt(2), the farthest vertex.
  to = Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitZ());
  const double chord = vertex_chord_bound(vertices, from, to, 0.0);
  EXPECT_GE(chord, 2.0 * std::sqrt(2.0));
  EXPECT_LT(chord, 2.0 * std::sqrt(2.0) * (1.0 + 1e-15));
}

// The Table 3 CP line after the PTP(WCS) approach to its start, among the near-miss post and
// the far obstacle (both clear of this path).
constexpr const char* kCpLinePath =
    "2\n2\n0.,20.,8.,0.,0.,1.,141.\n3.\n3.\n0.3\n3.\n3\n-20.,-5.,2.,0.,0.,1.,0.\n";

class CpLineCertificate : public ::testing::Test {
 protected:
  void SetUp() override {
    run_ = test::verify_ibm7545("bench-environment-near-miss.txt", kCpLinePath);
    ASSERT_EQ(run_.run.result.verdict, Verdict::kClear);
    document_ = certificate_to_json(run_.run.certificate);
    cell_.emplace(run_.robot, run_.environment, run_.setup.cell);
  }
  CheckReport check(const nlohmann::json& document) const {
    return check_certificate(run_.robot, run_.environment, run_.program, run_.kinematics,
                             certificate_from_json(document, "cert.json"));
  }
  // For transition k -> k+1 of segment `segment` (0-based) and hull i: M_h, L_h and M'_h
  // (proofs/motion-bound.md#lemma-axis-distance-along-step).
  std::tuple<double, double, double> bounds(int segment, std::size_t k, std::size_t i) const {
    const auto& steps = run_.run.certificate.segments.at(segment).steps;
    const Eigen::VectorXd& q0 = steps.at(k).q;
    const Eigen::VectorXd& q1 = steps.at(k + 1).q;
    const LinkHull& hull = cell_->hulls().at(i);
    kinematics::Workspace ws0(run_.robot), ws1(run_.robot);
    kinematics::forward_kinematics(cell_->chain(), q0, ws0);
    kinematics::forward_kinematics(cell_->chain(), q1, ws1);
    const double sum = cell_->radii().hull_motion_bound(hull.link, hull.hull, q1 - q0);
    const double chord = joint_linear_motion_bound(cell_->radii(), hull.link, hull.hull,
                                                   hull.raw_L, q0, ws0.X_WL[hull.link], q1,
                                                   ws1.X_WL[hull.link], cell_->placement_error());
    ProbeResult at0, at1;
    at0.X_WL = ws0.X_WL;
    at0.X_WJ = ws0.X_WJ;
    at1.X_WL = ws1.X_WL;
    at1.X_WJ = ws1.X_WJ;
    const StepAxisRadii step_radii(*cell_);
    std::vector<double> d0, d1;
    step_radii.axis_distances(at0, d0);
    step_radii.axis_distances(at1, d1);
    const double axis = step_radii.motion_bound(static_cast<int>(i), increments_up(q0, q1, {}), d0, d1);
    return {sum, chord, axis};
  }
  static bool names(const CheckReport& report, const std::string& failure) {
    for (const std::string& f : report.failures) {
      if (f.find(failure) != std::string::npos) return true;
    }
    return false;
  }
  test::Ibm7545Run run_;
  nlohmann::json document_;
  std::optional<RobotCell> cell_;
};

TEST_F(CpLineCertificate, CpStepsRecordTheChordBoundAndTheCheckerAcceptsIt) {
  const CheckReport report = check(document_);
  ASSERT_TRUE(report.accepted) << report.failures.front();
  // Segment 2 is the CP line: its recorded bounds are the chord bounds wherever those are
  // smaller, which for the quill (link 4) is at every step (joint 4 undoes the others' sweep;
  // the steps grow until the curvature term P_h / 3 eats most of the difference).
  const auto& steps = run_.run.certificate.segments.at(1).steps;
  ASSERT_GE(steps.size(), 3u);
  int quill_transitions = 0;
  for (std::size_t k = 0; k + 1 < steps.size(); ++k) {
    for (std::size_t i = 0; i < cell_->hulls().size(); ++i) {
      const auto [sum, chord, axis] = bounds(1, k, i);
      EXPECT_EQ(steps[k].to_next.hull_motion_bounds[i], std::min({sum, chord, axis}));
      if (cell_->hulls()[i].link == 4) {
        EXPECT_LT(chord, sum) << "step " << k;
        ++quill_transitions;
      }
    }
  }
  EXPECT_GT(quill_transitions, 0);
}

TEST_F(CpLineCertificate, CheckerRejectsACpBoundBelowTheChordBound) {
  const std::size_t quill = cell_->hulls().size() - 1;
  ASSERT_EQ(cell_->hulls()[quill].link, 4);
  const auto [sum, chord, axis] = bounds(1, 0, quill);
  ASSERT_LT(chord, sum);
  auto& bound = document_["segments"][1]["steps"][0]["to_next"]["hull_motion_bounds"][quill];
  bound = std::min(chord, axis) * 0.98;
  const CheckReport report = check(document_);
  EXPECT_FALSE(report.accepted);
  EXPECT_TRUE(names(report, "below the exact bound, the chord bound and the step's axis-distance bound"));
  // Just at the chord bound it holds (the checker decides the same inequality exactly).
  bound = chord;
  EXPECT_TRUE(check(document_).accepted);
}

TEST_F(CpLineCertificate, CheckerAllowsTheChordBoundOnlyOnCpSteps) {
  // Segment 1 is a PTP with independent trapezoid profiles: not joint-linear, so a bound
  // below M_h is rejected there even where the chord formula would give less.
  const auto& steps = run_.run.certificate.segments.at(0).steps;
  for (std::size_t k = 0; k + 1 < steps.size(); ++k) {
    for (std::size_t i = 0; i < cell_->hulls().size(); ++i) {
      const auto [sum, chord, axis] = bounds(0, k, i);
      const double proven = std::min(sum, axis);
      if (!(chord < 0.9 * proven)) continue;
      document_["segments"][0]["steps"][k]["to_next"]["hull_motion_bounds"][i] = 0.9 * proven;
      const CheckReport report = check(document_);
      EXPECT_FALSE(report.accepted);
      EXPECT_TRUE(names(report, "the recorded motion bound is below the exact bound"));
      return;
    }
  }
  FAIL() << "no PTP transition where the chord formula is below 0.9 min(M_h, M'_h)";
}

}  // namespace
}  // namespace grpvss::certify

// proofs/motion-bound.md#lemma-axis-distance-along-step as implemented
// (src/certify/step_axis_radius.cpp) and as the checker decides it: on random steps of the
// UR5e (../shared/robots) and the six-axis robot of data/, every hull vertex sampled along the
// joint-linear motion stays within the step's axis radius of every axis, and travels no
// farther than M'_h; M'_h is far below the configuration-independent M_h; the checker accepts
// a certificate resting on it and rejects a bound below it.
#include "certify/step_axis_radius.hpp"

#include <algorithm>
#include <random>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "certify/cell_probe.hpp"
#include "grpvss/cell/load_cell.hpp"
#include "grpvss/checker/certificate_checker.hpp"
#include "grpvss/evidence/certificate.hpp"
#include "grpvss/kinematics/forward_kinematics.hpp"
#include "support/data_paths.hpp"
#include "support/panda_self_run.hpp"

namespace grpvss::certify {
namespace {

using grpvss::test::kSourceDir;

ProbeResult frames_at(const RobotCell& cell, const Eigen::VectorXd& q) {
  kinematics::Workspace workspace(cell.robot());
  kinematics::forward_kinematics(cell.chain(), q, workspace);
  ProbeResult probe;
  probe.q = q;
  probe.X_WL = workspace.X_WL;
  probe.X_WJ = workspace.X_WJ;
  return probe;
}

double axis_distance(const Eigen::Vector3d& p, const Eigen::Isometry3d& X_WJ) {
  const Eigen::Vector3d offset = p - X_WJ.translation();
  const Eigen::Vector3d z = X_WJ.linear().col(2);
  return (offset - z * z.dot(offset)).norm();
}

struct SampledStep {
  double worst_axis_ratio = 0.0;   ///< sampled distance / rho over every vertex, axis, instant
  double worst_length_ratio = 0.0;  ///< sampled chord sum / M'_h
  double sum_axis_bound = 0.0;     ///< sum over hulls of M'_h
  double sum_joint_bound = 0.0;    ///< sum over hulls of M_h
};

// One joint-linear step q0 -> q1 sampled at `samples` instants.
SampledStep sample_step(const RobotCell& cell, const StepAxisRadii& radii, const Eigen::VectorXd& q0,
                        const Eigen::VectorXd& q1, int samples) {
  const int joints = cell.chain().joint_count();
  std::vector<double> d0, d1;
  radii.axis_distances(frames_at(cell, q0), d0);
  radii.axis_distances(frames_at(cell, q1), d1);
  const Eigen::VectorXd increments = increments_up(q0, q1, {});
  SampledStep result;
  kinematics::Workspace workspace(cell.robot());
  std::vector<std::vector<Eigen::Vector3d>> previous(cell.hulls().size());
  std::vector<std::vector<double>> lengths(cell.hulls().size());
  for (int k = 0; k <= samples; ++k) {
    kinematics::forward_kinematics(cell.chain(), q0 + (q1 - q0) * (k / double(samples)), workspace);
    for (std::size_t i = 0; i < cell.hulls().size(); ++i) {
      const LinkHull& hull = cell.hulls()[i];
      std::vector<Eigen::Vector3d> placed;
      kinematics::place_points(workspace.X_WL[static_cast<std::size_t>(hull.link)], hull.raw_L, placed);
      // rho_jh by the lemma's formula, written out here from R_jh, D_jh and the tail.
      for (int j = 1; j <= std::min(hull.link, joints); ++j) {
        if (cell.radii().joint_type(j) != JointType::kRevolute) continue;
        double tail = 0.0;
        for (int m = j + 1; m <= std::min(hull.link, joints); ++m) {
          tail += cell.radii().motion_bound_weight(hull.link, hull.hull, m) * increments[m - 1];
        }
        const std::size_t at = i * static_cast<std::size_t>(joints) + static_cast<std::size_t>(j - 1);
        const double rho = std::min(cell.radii().radius(hull.link, hull.hull, j),
                                    std::min(d0[at], d1[at]) + tail);
        for (const Eigen::Vector3d& p : placed) {
          result.worst_axis_ratio =
              std::max(result.worst_axis_ratio,
                       axis_distance(p, workspace.X_WJ[static_cast<std::size_t>(j - 1)]) / rho);
        }
      }
      if (k == 0) lengths[i].assign(placed.size(), 0.0);
      for (std::size_t v = 0; k > 0 && v < placed.size(); ++v) {
        lengths[i][v] += (placed[v] - previous[i][v]).norm();
      }
      previous[i] = placed;
    }
  }
  for (std::size_t i = 0; i < cell.hulls().size(); ++i) {
    const LinkHull& hull = cell.hulls()[i];
    const double bound = radii.motion_bound(static_cast<int>(i), increments, d0, d1);
    const double joint_sum = cell.radii().hull_motion_bound(hull.link, hull.hull, q1 - q0);
    EXPECT_LE(bound, joint_sum) << "hull " << i;
    result.sum_axis_bound += bound;
    result.sum_joint_bound += joint_sum;
    for (const double length : lengths[i]) {
      if (bound > 0.0) result.worst_length_ratio = std::max(result.worst_length_ratio, length / bound);
    }
  }
  return result;
}

struct RandomSteps {
  double worst_axis_ratio = 0.0;
  double worst_length_ratio = 0.0;
  double axis_over_joint = 0.0;  ///< sum of M'_h over sum of M_h, every step and hull
};

RandomSteps random_steps(const std::string& cell_file, int steps, double largest_increment,
                         std::uint64_t seed) {
  const cell::LoadedCell loaded = cell::load_cell(cell_file);
  CellSettings settings;
  settings.tolerance = loaded.tolerance;
  const RobotCell cell(loaded.robot, loaded.environment, settings);
  const StepAxisRadii radii(cell);
  std::mt19937_64 generator(seed);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  RandomSteps result;
  double axis_sum = 0.0, joint_sum = 0.0;
  for (int step = 0; step < steps; ++step) {
    const int joints = cell.chain().joint_count();
    Eigen::VectorXd q0(joints), q1(joints);
    for (int j = 0; j < joints; ++j) {
      const kinematics::ChainJoint& joint = cell.chain().joints[static_cast<std::size_t>(j)];
      const double low = std::max(joint.minimum, -3.0), high = std::min(joint.maximum, 3.0);
      q0[j] = low + (high - low) * 0.5 * (1.0 + unit(generator));
      q1[j] = std::clamp(q0[j] + largest_increment * unit(generator), low, high);
    }
    const SampledStep sampled = sample_step(cell, radii, q0, q1, 200);
    result.worst_axis_ratio = std::max(result.worst_axis_ratio, sampled.worst_axis_ratio);
    result.worst_length_ratio = std::max(result.worst_length_ratio, sampled.worst_length_ratio);
    axis_sum += sampled.sum_axis_bound;
    joint_sum += sampled.sum_joint_bound;
  }
  result.axis_over_joint = axis_sum / joint_sum;
  return result;
}

TEST(LemmaAxisDistanceAlongStep, SampledAxisDistancesStayWithinTheStepRadius) {
  for (const std::string& file : {kSourceDir + "/tests/data/cells/ur5e-post.yaml",
                                  kSourceDir + "/data/sixaxis/cell.yaml"}) {
    const RandomSteps steps = random_steps(file, 30, 0.3, 11);
    std::printf("%s: worst sampled axis distance / rho %.4f, path length / M'_h %.4f, "
                "sum M'_h / sum M_h %.3f\n",
                file.c_str(), steps.worst_axis_ratio, steps.worst_length_ratio,
                steps.axis_over_joint);
    EXPECT_LE(steps.worst_axis_ratio, 1.0) << file;
    EXPECT_LE(steps.worst_length_ratio, 1.0) << file;
    // Not vacuous: somewhere a vertex comes within 2x of its step radius.
    EXPECT_GT(steps.worst_axis_ratio, 0.5) << file;
  }
}

TEST(LemmaAxisDistanceAlongStep, TheStepRadiusIsTighterThanTheConfigurationIndependentOne) {
  // The UR5e folded at home (elbow up, wrist over the base): joint 1 turns 0.1 rad. R_1h is
  // the reach of the stretched arm; the wrist hulls stay within ~0.2 m of joint 1's axis.
  const cell::LoadedCell loaded = cell::load_cell(kSourceDir + "/tests/data/cells/ur5e-post.yaml");
  CellSettings settings;
  settings.tolerance = loaded.tolerance;
  const RobotCell cell(loaded.robot, loaded.environment, settings);
  const StepAxisRadii radii(cell);
  Eigen::VectorXd q0(6), q1(6);
  q0 << 0, -1.5708, 1.5708, 0, 0, 0;
  q1 = q0;
  q1[0] += 0.1;
  std::vector<double> d0, d1;
  radii.axis_distances(frames_at(cell, q0), d0);
  radii.axis_distances(frames_at(cell, q1), d1);
  const Eigen::VectorXd increments = increments_up(q0, q1, {});
  for (std::size_t i = 0; i < cell.hulls().size(); ++i) {
    const LinkHull& hull = cell.hulls()[i];
    if (hull.link < 1) continue;
    const double bound = radii.motion_bound(static_cast<int>(i), increments, d0, d1);
    const double joint_sum = cell.radii().hull_motion_bound(hull.link, hull.hull, q1 - q0);
    // Joint 1 alone: M'_h = 0.1 min(R_1h, D_1h) exactly up to rounding; D at both ends is the
    // same distance (a turn about the axis keeps it).
    EXPECT_NEAR(bound, 0.1 * std::min(cell.radii().radius(hull.link, hull.hull, 1), d0[i * 6]),
                1e-12) << "hull " << i;
    EXPECT_NEAR(d0[i * 6], d1[i * 6], 1e-9) << "hull " << i;
    if (hull.link >= 4) {
      EXPECT_LT(bound, 0.6 * joint_sum) << "link " << hull.link << " hull " << hull.hull;
    }
  }
}

// The Panda's clear path of tests/data/cells (synchronized PTP, claim motion): its steps record
// M'_h wherever it is below M_h, the checker re-derives it, and a bound just below what the
// verifier proves is rejected.
TEST(LemmaAxisDistanceAlongStep, TheCheckerAcceptsTheStepBoundAndRejectsOneBelowIt) {
  const test::PandaSelfRun run = test::run_panda_self("panda-clear.txt");
  const Certificate& certificate = run.verified.certificate;
  ASSERT_TRUE(test::check_panda_self(run, certificate).accepted);
  CellSettings settings;
  settings.tolerance = run.cell.tolerance;
  const RobotCell cell(run.cell.robot, run.cell.environment, settings);
  const StepAxisRadii radii(cell);
  // Find a transition whose recorded bound is below M_h (it rests on M'_h).
  for (std::size_t s = 0; s < certificate.segments.size(); ++s) {
    const auto& steps = certificate.segments[s].steps;
    for (std::size_t k = 0; k + 1 < steps.size(); ++k) {
      for (std::size_t i = 0; i < cell.hulls().size(); ++i) {
        const LinkHull& hull = cell.hulls()[i];
        const double recorded = steps[k].to_next.hull_motion_bounds[i];
        const double joint_sum = cell.radii().hull_motion_bound(hull.link, hull.hull,
                                                                steps[k + 1].q - steps[k].q);
        if (!(recorded < 0.8 * joint_sum)) continue;
        std::vector<double> d0, d1;
        radii.axis_distances(frames_at(cell, steps[k].q), d0);
        radii.axis_distances(frames_at(cell, steps[k + 1].q), d1);
        const double axis =
            radii.motion_bound(static_cast<int>(i), increments_up(steps[k].q, steps[k + 1].q, {}), d0, d1);
        EXPECT_EQ(recorded, axis);
        nlohmann::json document = certificate_to_json(certificate);
        document["segments"][s]["steps"][k]["to_next"]["hull_motion_bounds"][i] = 0.97 * axis;
        const CheckReport report =
            test::check_panda_self(run, certificate_from_json(document, "cert.json"));
        EXPECT_FALSE(report.accepted);
        bool named = false;
        for (const std::string& failure : report.failures) {
          named = named || failure.find("below the exact bound and the step's axis-distance bound") !=
                               std::string::npos;
        }
        EXPECT_TRUE(named);
        return;
      }
    }
  }
  FAIL() << "no transition rests on M'_h";
}

}  // namespace
}  // namespace grpvss::certify

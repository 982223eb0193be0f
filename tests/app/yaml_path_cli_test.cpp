// A YAML path with absolute targets (issue #20 point 6, docs/input-formats.md#yaml-path) on the
// UR5e cell of tests/data/cells/ur5e-post-no-self.yaml (base 0.8 m up, turned 0.25 rad): a PTP to
// the pose the arm has at q1 ends at q1, whether the pose is written in the world or in the
// base frame, in metres or millimetres; an absolute CP line runs exactly as the thesis path's
// "keep the orientation" line to the same point; the certificate of a YAML path is ACCEPTED by
// check-certificate, and REJECTED when the YAML file is edited.
#include <cmath>
#include <fstream>
#include <string>
#include <vector>

#include <Eigen/Geometry>
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "grpvss/cell/model_inputs.hpp"
#include "grpvss/kinematics/forward_kinematics.hpp"
#include "grpvss/kinematics/kinematic_chain.hpp"
#include "support/cli_run.hpp"
#include "support/data_paths.hpp"
#include "support/text_files.hpp"

namespace {

using grpvss::test::kUr5ePostNoSelfCell;
const double kRadiansPerDegree = std::acos(-1.0) / 180.0;

using grpvss::test::CliRun;
using grpvss::test::run_cli;

class YamlPathCli : public ::testing::Test {
 protected:
  void SetUp() override { directory_ = grpvss::test::make_temporary_directory("yaml-path-cli"); }
  void TearDown() override { std::filesystem::remove_all(directory_); }
  void write(const std::string& name, const std::string& text) const {
    std::ofstream(directory_ + "/" + name) << text;
  }
  nlohmann::json verify(const std::string& path, const std::string& name) const {
    const CliRun run = run_cli(directory_, "verify --cell " + kUr5ePostNoSelfCell + " --path " + path + " --json " +
                                               name + ".json --certificate " + name + ".cert --no-cache");
    EXPECT_EQ(run.exit_code, 0) << run.out << run.err;
    return nlohmann::json::parse(grpvss::test::read_text_file(directory_ + "/" + name + ".json"));
  }
  std::string directory_;
};

// X_WE of the cell's robot at q (rad), by the library's forward kinematics.
Eigen::Isometry3d pose_at(const std::vector<double>& q_deg) {
  const grpvss::cell::ModelInputs model = grpvss::cell::load_model_inputs({"", "", kUr5ePostNoSelfCell, {}});
  Eigen::VectorXd q(6);
  for (int j = 0; j < 6; ++j) q[j] = q_deg[static_cast<std::size_t>(j)] * kRadiansPerDegree;
  return grpvss::kinematics::end_effector_pose(grpvss::kinematics::make_chain(model.robot), q);
}

std::string xyz_quaternion(const Eigen::Isometry3d& X, double scale) {
  const Eigen::Quaterniond q(X.linear());
  return fmt::format("xyz: [{}, {}, {}], quaternion: {{w: {}, x: {}, y: {}, z: {}}}",
                     X.translation().x() * scale, X.translation().y() * scale,
                     X.translation().z() * scale, q.w(), q.x(), q.y(), q.z());
}

std::vector<double> end_joints(const nlohmann::json& report, std::size_t segment) {
  return report["segments"][segment]["end_joint_values"].get<std::vector<double>>();
}

TEST_F(YamlPathCli, APoseTargetInTheWorldOrTheBaseEndsWhereTheJointsWere) {
  const std::vector<double> q1{-30, -90, 90, 0, 30, 0};
  const Eigen::Isometry3d X_WE = pose_at(q1);
  Eigen::Isometry3d X_WR = Eigen::Isometry3d::Identity();
  X_WR.translate(Eigen::Vector3d(0, 0, 0.8));
  X_WR.rotate(Eigen::AngleAxisd(0.25, Eigen::Vector3d::UnitZ()));
  write("world.yaml", "units: {length: m, angle: deg}\nsegments:\n  - ptp: {pose: {" +
                          xyz_quaternion(X_WE, 1.0) + "}, speed: 30}\n");
  write("base.yaml", "units: {length: mm, angle: deg}\nsegments:\n  - ptp: {pose: {" +
                         xyz_quaternion(X_WR.inverse() * X_WE, 1000.0) + ", frame: base}, speed: 30}\n");
  for (const char* name : {"world", "base"}) {
    const nlohmann::json report = verify(std::string(name) + ".yaml", name);
    EXPECT_EQ(report["verdict"], "CLEAR") << name;
    EXPECT_EQ(report["segments"][0]["kind"], "ptp-world");
    EXPECT_EQ(report["segments"][0]["target_orientation"], "absolute");
    const std::vector<double> reached = end_joints(report, 0);
    for (std::size_t j = 0; j < 6; ++j) EXPECT_NEAR(reached[j], q1[j], 1e-6) << name << " joint " << j;
    const CliRun check = run_cli(directory_, "check-certificate --cell " + kUr5ePostNoSelfCell + " --path " +
                                                 name + ".yaml " + name + ".cert");
    EXPECT_EQ(check.exit_code, 0) << check.out << check.err;
    EXPECT_EQ(check.out.rfind("ACCEPTED", 0), 0u) << check.out;
  }
  // The certificate binds the YAML file: an edited target is rejected.
  write("world.yaml", "units: {length: m, angle: deg}\nsegments:\n  - ptp: {pose: {" +
                          xyz_quaternion(X_WE, 1.0) + "}, speed: 31}\n");
  const CliRun edited = run_cli(directory_, "check-certificate --cell " + kUr5ePostNoSelfCell +
                                                " --path world.yaml world.cert");
  EXPECT_EQ(edited.exit_code, 1) << edited.out << edited.err;
}

TEST_F(YamlPathCli, AnAbsoluteLineRunsAsTheThesisLineThatKeepsTheOrientation) {
  const std::vector<double> q1{-30, -90, 90, 0, 30, 0};
  const Eigen::Isometry3d X_WE = pose_at(q1);
  Eigen::Isometry3d X_end = X_WE;
  X_end.translation() += Eigen::Vector3d(0.05, 0.02, -0.03);
  write("line.yaml", "units: {length: m, angle: deg}\nsegments:\n"
                     "  - ptp: {joints: [-30, -90, 90, 0, 30, 0], speed: 30}\n"
                     "  - lin: {pose: {" + xyz_quaternion(X_end, 1.0) + "}}\n");
  write("line.txt", fmt::format("2\n1\n-30,30\n-90,30\n90,30\n0,30\n30,30\n0,30\n3\n{} {} {} 0 0 1 0\n",
                                X_end.translation().x(), X_end.translation().y(), X_end.translation().z()));
  const nlohmann::json yaml = verify("line.yaml", "yaml");
  const nlohmann::json thesis = verify("line.txt", "thesis");
  EXPECT_EQ(yaml["verdict"], thesis["verdict"]);
  EXPECT_EQ(yaml["steps"].size(), thesis["steps"].size());
  EXPECT_EQ(yaml["segments"][1]["kind"], "cp-line");
  const std::vector<double> a = end_joints(yaml, 1), b = end_joints(thesis, 1);
  for (std::size_t j = 0; j < 6; ++j) EXPECT_NEAR(a[j], b[j], 1e-9) << "joint " << j;
}

}  // namespace

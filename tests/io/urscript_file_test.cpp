/// The URScript reader: the UR5e pick-and-place sample read into exact motions, the
/// warnings, and every kind of rejected input with its file, line and message.

#include "grpvss/io/urscript_file.hpp"

#include <string>

#include <gtest/gtest.h>

#include "io/program_references.hpp"
#include "support/input_error_expectations.hpp"

namespace grpvss::io {
namespace {

using grpvss::testing::cartesian;
using grpvss::testing::expect_input_error;
using grpvss::testing::expect_matrix_near;
using grpvss::testing::expect_vector_near;
using grpvss::testing::expect_warning;
using grpvss::testing::joints;
using grpvss::testing::kPi;
using grpvss::testing::rodrigues_reference;
using grpvss::testing::vector6;

const std::string kUrScriptSample = std::string(GRPVSS_SOURCE_DIR) + "/data/programs/ur5e_pick_and_place.script";
constexpr double kRoughPi = 3.14159265358979;  // as the sample writes it

RobotProgram parse_script(const std::string& text) { return parse_urscript(text, "t.script"); }

void expect_script_error(const std::string& text, int line, const std::string& message) {
  expect_input_error([&] { parse_script(text); }, "t.script", line, "t.script:" + std::to_string(line) + ": " + message);
}

/// The pose p[x, y, z, rx, ry, rz] as the sample means it, composed by hand.
struct Pose {
  Eigen::Matrix3d R;
  Eigen::Vector3d t;
  Pose operator*(const Pose& other) const { return {R * other.R, R * other.t + t}; }
};
Pose pose(double x, double y, double z, double rx, double ry, double rz) {
  return {rodrigues_reference({rx, ry, rz}), {x, y, z}};
}

void expect_pose(const ProgramTarget& target, const Pose& expected) {
  const CartesianTarget& c = cartesian(target);
  expect_vector_near(c.p_BT, expected.t, 1e-15);
  expect_matrix_near(c.R_BT.toRotationMatrix(), expected.R, 1e-15);
}

TEST(UrScriptFile, ReadsThePickAndPlaceSample) {
  const RobotProgram program = read_urscript_file(kUrScriptSample);
  EXPECT_EQ(program.language, ProgramLanguage::kUrScript);
  EXPECT_EQ(program.name, "pick_and_place");
  EXPECT_EQ(program.files, std::vector<std::string>{kUrScriptSample});
  ASSERT_EQ(program.motions.size(), 8u);
  const auto& m = program.motions;

  const Eigen::VectorXd home = vector6(0.0, -1.5708, 1.5708, -1.5708, -1.5708, 0.0);
  const Pose above_pick = pose(0.4, -0.2, 0.3, 0, kRoughPi, 0);
  const Pose pick = pose(0.4, -0.2, 0.1, 0, kRoughPi, 0);
  const Pose place = pose(-0.1, 0.45, 0.0, 0, 0, 90 * kPi / 180) * pose(0, 0, 0.12, 0, kRoughPi, 0);
  const Pose above_place = place * pose(0, 0, -0.1, 0, 0, 0);

  const int lines[] = {17, 18, 19, 21, 22, 23, 25, 26};
  const MotionKind kinds[] = {MotionKind::kJoint, MotionKind::kJoint, MotionKind::kLinear, MotionKind::kLinear,
                              MotionKind::kCircular, MotionKind::kLinear, MotionKind::kLinear, MotionKind::kJoint};
  const char* names[] = {"home_q", "get_inverse_kin(above_pick, qnear=home_q)", "pick", "above_pick",
                         "above_place", "place", "above_place", "home_q"};
  for (std::size_t i = 0; i < m.size(); ++i) {
    EXPECT_EQ(m[i].line, lines[i]) << i;
    EXPECT_EQ(m[i].file, kUrScriptSample) << i;
    EXPECT_EQ(m[i].kind, kinds[i]) << i;
    EXPECT_EQ(m[i].target_name, names[i]) << i;
    EXPECT_EQ(m[i].X_FT.translation(), Eigen::Vector3d(0, 0, 0.15)) << i;
    EXPECT_EQ(m[i].X_FT.linear(), Eigen::Matrix3d::Identity()) << i;
    EXPECT_EQ(m[i].tool_name, "set_tcp(p[0.0, 0.0, 0.15, 0.0, 0.0, 0.0])") << i;
    EXPECT_TRUE(m[i].X_RB.isApprox(Eigen::Isometry3d::Identity(), 0.0)) << i;
    EXPECT_EQ(m[i].base_name, "base") << i;
    EXPECT_EQ(m[i].via.has_value(), i == 4) << i;
  }
  EXPECT_EQ(joints(m[0].target), home);
  expect_pose(m[1].target, above_pick);  // get_inverse_kin(above_pick, qnear=home_q): the pose, nearest home
  const auto* near = std::get_if<UrNearestJoints>(&cartesian(m[1].target).configuration);
  ASSERT_NE(near, nullptr);
  EXPECT_EQ(near->qnear, home);
  for (const std::size_t i : {2, 3, 5, 6}) {
    EXPECT_TRUE(std::holds_alternative<std::monostate>(cartesian(m[i].target).configuration)) << i;
  }
  expect_pose(m[2].target, pick);
  expect_pose(m[3].target, above_pick);
  expect_pose(*m[4].via, pose(0.25, 0.2, 0.3, 0, kRoughPi, 0));
  EXPECT_EQ(m[4].via_name, "");
  expect_pose(m[4].target, above_place);
  expect_pose(m[5].target, place);
  expect_pose(m[6].target, above_place);
  EXPECT_EQ(joints(m[7].target), home);

  // movej: a, v are joint acceleration and speed; movel/movec: TCP. Defaults 1.4/1.05, 1.2/0.25.
  EXPECT_EQ(m[0].speed.joint_acceleration, 1.4);
  EXPECT_EQ(m[0].speed.joint_speed, 1.05);
  EXPECT_FALSE(m[0].speed.tcp_speed.has_value());
  EXPECT_EQ(m[1].speed.joint_acceleration, 1.2);
  EXPECT_EQ(m[1].speed.joint_speed, 0.8);
  EXPECT_EQ(m[2].speed.tcp_acceleration, 0.5);
  EXPECT_EQ(m[2].speed.tcp_speed, 0.1);
  EXPECT_FALSE(m[2].speed.joint_speed.has_value());
  EXPECT_EQ(m[3].speed.tcp_acceleration, 0.5);  // positional a, v, t, r
  EXPECT_EQ(m[3].speed.tcp_speed, 0.25);
  EXPECT_EQ(m[4].speed.tcp_speed, 0.2);
  EXPECT_EQ(m[5].speed.tcp_acceleration, 1.2);
  EXPECT_EQ(m[5].speed.tcp_speed, 0.1);
  EXPECT_EQ(m[6].speed.tcp_acceleration, 1.2);
  EXPECT_EQ(m[6].speed.tcp_speed, 0.25);
  EXPECT_EQ(m[7].speed.duration, 3.0);
  for (std::size_t i = 0; i < 7; ++i) EXPECT_FALSE(m[i].speed.duration.has_value()) << i;

  const double radii[] = {0, 0.05, 0, 0.02, 0.01, 0, 0, 0};
  for (std::size_t i = 0; i < m.size(); ++i) {
    EXPECT_EQ(m[i].blend.kind, radii[i] > 0 ? BlendKind::kDistance : BlendKind::kExactStop) << i;
    EXPECT_EQ(m[i].blend.radius, radii[i] > 0 ? std::optional<double>(radii[i]) : std::nullopt) << i;
  }

  // grip() runs twice: its statements are warned about once.
  ASSERT_EQ(program.warnings.size(), 3u);
  expect_warning(program.warnings[0], kUrScriptSample, 5, "not read: set_payload(1.2, [0.0, 0.0, 0.05])");
  expect_warning(program.warnings[1], kUrScriptSample, 14, "not read: set_standard_digital_out(0, closed)");
  expect_warning(program.warnings[2], kUrScriptSample, 15, "not read: sleep(0.3)");
}

TEST(UrScriptFile, RotationVectorQuarterTurnAboutZMapsXToY) {
  const RobotProgram program = parse_script("set_tcp(p[0, 0, 0, 0, 0, 0])\nmovel(p[0.1, 0.2, 0.3, 0, 0, 1.5707963267948966])\n");
  const CartesianTarget& target = cartesian(program.motions.at(0).target);
  expect_vector_near(target.R_BT * Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY(), 1e-15);
  EXPECT_EQ(target.p_BT, Eigen::Vector3d(0.1, 0.2, 0.3));
}

TEST(UrScriptFile, TopLevelStatementsControlFlowAndCallsWithArguments) {
  const std::string text =
      "def approach(target, height):\n"           // 1
      "  movel(pose_trans(target, p[0, 0, -height, 0, 0, 0]), v=0.5)\n"
      "end\n"
      "a = p[0.3, 0, 0.2, 0, 0, 0]\n"             // 4
      "while True:\n"                             // 5
      "  if get_standard_digital_in(2):\n"        // 6
      "    approach(a, 0.05)\n"                   // 7
      "  else:\n"                                 // 8
      "    movej([0, -1, 1, 0, 1, 0], r=0.1)\n"   // 9
      "  end\n"
      "end\n"
      "movec(a, a, mode=1)\n";                    // 12
  const RobotProgram program = parse_script(text);
  EXPECT_EQ(program.name, "");
  ASSERT_EQ(program.motions.size(), 3u);
  EXPECT_EQ(program.motions[0].line, 2);
  expect_vector_near(cartesian(program.motions[0].target).p_BT, {0.3, 0, 0.15}, 1e-15);
  EXPECT_EQ(program.motions[0].speed.tcp_speed, 0.5);
  EXPECT_EQ(program.motions[1].line, 9);
  EXPECT_EQ(joints(program.motions[1].target), vector6(0, -1, 1, 0, 1, 0));
  EXPECT_EQ(program.motions[1].blend.radius, 0.1);
  EXPECT_EQ(program.motions[2].kind, MotionKind::kCircular);
  ASSERT_EQ(program.warnings.size(), 5u);
  const std::string note = " (the statements inside are read once, in order)";
  expect_warning(program.warnings[0], "t.script", 5, "control flow not evaluated: while True:" + note);
  expect_warning(program.warnings[1], "t.script", 6, "control flow not evaluated: if get_standard_digital_in(2):" + note);
  expect_warning(program.warnings[2], "t.script", 2,
                 "no set_tcp before the first motion: the tool flange is taken as the TCP (the controller uses the installation's active TCP)");
  expect_warning(program.warnings[3], "t.script", 8, "control flow not evaluated: else:" + note);
  expect_warning(program.warnings[4], "t.script", 12,
                 "movec mode=1 (orientation fixed to the arc) is not represented: the orientation is read as interpolated");
  EXPECT_EQ(program.motions[0].tool_name, "flange (no set_tcp)");
}

TEST(UrScriptFile, GetInverseKinIsThePoseWithTheNearestConfiguration) {
  const RobotProgram program = parse_script("set_tcp(p[0, 0, 0, 0, 0, 0])\nmovel(get_inverse_kin(p[0.3, 0, 0.2, 0, 0, 0]))\n");
  const CartesianTarget& target = cartesian(program.motions.at(0).target);
  EXPECT_EQ(target.p_BT, Eigen::Vector3d(0.3, 0, 0.2));
  const auto* near = std::get_if<UrNearestJoints>(&target.configuration);
  ASSERT_NE(near, nullptr);
  EXPECT_EQ(near->qnear.size(), 0);  // none given: nearest the joints the robot has then
}

TEST(UrScriptFile, UnknownValuesAreWarnedAndRejectedWhenAMotionNeedsThem) {
  const RobotProgram program = parse_script("x = get_actual_tcp_pose()\nmovej([0, 0, 0, 0, 0, 0])\n");
  ASSERT_EQ(program.warnings.size(), 2u);
  expect_warning(program.warnings[0], "t.script", 1,
                 "'x' is not computed: get_actual_tcp_pose(), which the reader does not evaluate");
  expect_script_error("x = get_actual_tcp_pose()\nmovel(x)\n", 2,
               "expected a joint list or pose the reader can compute for pose of movel, found "
               "get_actual_tcp_pose(), which the reader does not evaluate");
  expect_script_error("movel(wp9)\n", 1,
               "expected a joint list or pose the reader can compute for pose of movel, found "
               "'wp9', which this program does not assign before line 1");
  expect_script_error("movej(get_inverse_kin(p[0.3, 0, 0.2, 0, 0, 0], tcp=p[0, 0, 0.1, 0, 0, 0]))\n", 1,
               "expected a joint list or pose the reader can compute for q of movej, found "
               "get_inverse_kin() for a tcp= other than the active one (not read)");
  expect_script_error("movel(get_inverse_kin(p[0.3, 0, 0.2, 0, 0, 0], [0, 0, 0]))\n", 1,
               "expected 6 joint values for qnear of get_inverse_kin, found a list of 3 numbers");
}

TEST(UrScriptFile, RejectsMalformedProgramsNamingFileLineAndExpectation) {
  expect_script_error("def main():\n  movel([0, 0, 0, 0, 0])\nend\n", 2, "expected 6 joint values for pose of movel, found 5");
  expect_script_error("\nmovep(p[0, 0, 0.1, 0, 0, 0])\n", 2, "expected a motion the reader reads (movej, movel, movec), found 'movep'");
  expect_script_error("def main():\n  movej([0, 0, 0, 0, 0, 0])\n", 3, "expected an 'end' closing the 'def' of line 1, found end of file");
  expect_script_error("movej([0, 0, 0, 0, 0, 0], speed=1)\n", 1, "expected a parameter of movej, found 'speed'");
  expect_script_error("movel(p[0, 0, 0, 0, 0, 0], r=-0.1)\n", 1,
               "expected a non-negative number the reader can compute for r of movel, found -0.1");
  expect_script_error("movel(p[1, 2, 3, 0, 0, 0], a=)\n", 1, "expected an argument, found ')'");
  expect_script_error("movel(p[1, 2, 3])\n", 1, "expected 6 numbers in p[x, y, z, rx, ry, rz], found a list of 3 numbers");
  expect_script_error("movel()\n", 1, "expected a value for pose of movel, found none");
  expect_script_error("x = 1\nelif x:\n", 2, "expected 'elif' inside an if block, found 'elif' outside one");
  expect_script_error("end\n", 1, "expected a statement ('end' closes no open block here), found 'end'");
  expect_script_error("# nothing but a comment\n", 2, "expected a URScript program: statements, or a def ... end, found no statement");
  expect_script_error("set_tcp([0, 0, 0.1, 0, 0, 0])\n", 1, "expected a pose the reader can compute for set_tcp, found a list of 6 numbers");
  expect_script_error("if x > 1\n  movej([0, 0, 0, 0, 0, 0])\nend\n", 1, "expected ':' at the end of the if line, found '1'");
  expect_script_error("def f():\n  f()\nend\nf()\n", 2,
               "expected calls nested at most 32 deep (recursion is not evaluated), found a call of f nested deeper");
  expect_script_error("def f():\nend\ndef f():\nend\n", 3, "expected a function name not defined before (line 1), found 'f'");
  expect_script_error("x = [1, 2] + 1\n", 1, "expected numbers for '+', found a list of 2 numbers");
  expect_script_error("5 = x\n", 1, "expected a statement, found '5'");
  // An index far outside every integer type is reported, not converted (the fuzzer's finding).
  expect_script_error("x = [1, 2][7.7e89]\n", 1, "expected an index below 2, found 7.7e+89");
  expect_script_error("x = p[0, 0, 0, 0, 0, 0][-1e300]\n", 1, "expected a pose index 0..5, found -1e+300");
}

TEST(UrScriptFile, AStatementContinuesInsideBrackets) {
  const RobotProgram program = parse_script("movej([0, 0,\n  0, 0, 0, 0],\n  a=1)\nmovej([0, 0, 0, 0, 0, 0.5])\n");
  ASSERT_EQ(program.motions.size(), 2u);
  EXPECT_EQ(program.motions[0].line, 1);
  EXPECT_EQ(program.motions[0].speed.joint_acceleration, 1.0);
  EXPECT_EQ(program.motions[1].line, 4);
  EXPECT_EQ(joints(program.motions[1].target), vector6(0, 0, 0, 0, 0, 0.5));
}

TEST(UrScriptFile, AMissingFileIsAnInputError) {
  EXPECT_THROW(read_urscript_file("/nonexistent/x.script"), InputError);
}

}  // namespace
}  // namespace grpvss::io

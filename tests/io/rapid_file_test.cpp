/// The ABB RAPID reader: the gluing sample read into exact motions (targets, tool and work
/// object frames, speed and zone data), the warnings, and rejected input with file, line and
/// message.

#include "grpvss/io/rapid_file.hpp"

#include <string>

#include <gtest/gtest.h>

#include "grpvss/io/units.hpp"
#include "io/program_references.hpp"
#include "support/input_error_expectations.hpp"

namespace grpvss::io {
namespace {

using grpvss::testing::axis_rotation;
using grpvss::testing::cartesian;
using grpvss::testing::expect_input_error;
using grpvss::testing::expect_matrix_near;
using grpvss::testing::expect_vector_near;
using grpvss::testing::expect_warning;
using grpvss::testing::joints;
using grpvss::testing::kDegree;
using grpvss::testing::quaternion_reference;
using grpvss::testing::vector6;

const std::string kSample = std::string(GRPVSS_SOURCE_DIR) + "/data/programs/irb_glue.mod";
const std::string kUnused = "[9E9, 9E9, 9E9, 9E9, 9E9, 9E9]";

RobotProgram parse_rapid_module(const std::string& text) { return parse_rapid(text, "t.mod"); }

void expect_rapid_error(const std::string& text, int line, const std::string& message) {
  expect_input_error([&] { parse_rapid_module(text); }, "t.mod", line, "t.mod:" + std::to_string(line) + ": " + message);
}

/// A module whose PROC main holds `body` (body lines start at line 3).
std::string module(const std::string& data, const std::string& body) {
  return "MODULE m\n" + data + "PROC main()\n" + body + "ENDPROC\nENDMODULE\n";
}

std::string robtarget(const std::string& trans, const std::string& rot = "[1, 0, 0, 0]") {
  return "[" + trans + ", " + rot + ", [0, 0, 0, 0], " + kUnused + "]";
}

void expect_configuration(const CartesianTarget& target, int cf1, int cf4, int cf6, int cfx) {
  const auto* conf = std::get_if<RapidConfData>(&target.configuration);
  ASSERT_NE(conf, nullptr);
  EXPECT_EQ(conf->cf1, cf1);
  EXPECT_EQ(conf->cf4, cf4);
  EXPECT_EQ(conf->cf6, cf6);
  EXPECT_EQ(conf->cfx, cfx);
}

TEST(RapidFile, ReadsTheGluingSample) {
  const RobotProgram program = read_rapid_file(kSample);
  EXPECT_EQ(program.language, ProgramLanguage::kRapid);
  EXPECT_EQ(program.name, "main");
  EXPECT_EQ(program.files, std::vector<std::string>{kSample});
  ASSERT_EQ(program.motions.size(), 8u);
  const auto& m = program.motions;

  const int lines[] = {22, 23, 24, 33, 34, 35, 28, 29};
  const MotionKind kinds[] = {MotionKind::kJoint,  MotionKind::kJoint,  MotionKind::kLinear, MotionKind::kLinear,
                              MotionKind::kLinear, MotionKind::kCircular, MotionKind::kLinear, MotionKind::kJoint};
  const char* names[] = {"jHome", "Offs(pStart, 0, 0, 100)", "pStart", "pCorner{1}", "pCorner{2}", "pArcEnd",
                         "RelTool(pArcEnd, 0, 0, -100\\Rz:=45)", "jHome"};
  // tGlue: tframe [[0, 0, 120], [0.707106781, 0, 0.707106781, 0]]; wobjTable: uframe
  // [[600, -300, 200], [0.707106781, 0, 0, 0.707106781]] times oframe [[0, 0, 10], identity].
  const Eigen::Matrix3d R_FT = quaternion_reference(0.707106781, 0, 0.707106781, 0);
  const Eigen::Matrix3d R_RB = quaternion_reference(0.707106781, 0, 0, 0.707106781);
  const Eigen::Vector3d p_RB = Eigen::Vector3d(0.6, -0.3, 0.2) + R_RB * Eigen::Vector3d(0, 0, 0.01);
  for (std::size_t i = 0; i < m.size(); ++i) {
    EXPECT_EQ(m[i].line, lines[i]) << i;
    EXPECT_EQ(m[i].kind, kinds[i]) << i;
    EXPECT_EQ(m[i].target_name, names[i]) << i;
    EXPECT_EQ(m[i].file, kSample) << i;
    const bool glue = i != 0 && i != 7;
    EXPECT_EQ(m[i].tool_name, glue ? "tGlue" : "tool0") << i;
    EXPECT_EQ(m[i].base_name, glue ? "wobjTable" : "wobj0") << i;
    if (glue) {
      EXPECT_EQ(m[i].X_FT.translation(), Eigen::Vector3d(0, 0, 0.12)) << i;
      expect_matrix_near(m[i].X_FT.linear(), R_FT, 1e-15);
      expect_vector_near(m[i].X_RB.translation(), p_RB, 1e-15);
      expect_matrix_near(m[i].X_RB.linear(), R_RB, 1e-15);
    } else {
      EXPECT_TRUE(m[i].X_FT.isApprox(Eigen::Isometry3d::Identity(), 0.0)) << i;
      EXPECT_TRUE(m[i].X_RB.isApprox(Eigen::Isometry3d::Identity(), 0.0)) << i;
    }
  }
  const Eigen::VectorXd home = vector6(0, -20 * kDegree, 20 * kDegree, 0, 60 * kDegree, 0);
  EXPECT_EQ(joints(m[0].target), home);
  EXPECT_EQ(joints(m[7].target), home);
  const Eigen::Matrix3d down = quaternion_reference(0, 0, 1, 0);  // [0, 0, 1, 0]: x to -x, z to -z
  const auto expect_target = [&](const ProgramTarget& target, const Eigen::Vector3d& p_mm, const Eigen::Matrix3d& R) {
    expect_vector_near(cartesian(target).p_BT, p_mm / 1000, 1e-15);
    expect_matrix_near(cartesian(target).R_BT.toRotationMatrix(), R, 1e-15);
  };
  expect_target(m[1].target, {0, 0, 150}, down);  // Offs(pStart, 0, 0, 100)
  expect_target(m[2].target, {0, 0, 50}, down);
  expect_target(m[3].target, {200, 0, 0}, down);
  expect_configuration(cartesian(m[3].target), 0, 0, 0, 0);
  expect_target(m[4].target, {200, 150, 0}, down);
  expect_configuration(cartesian(m[4].target), -1, 0, -1, 1);
  expect_target(*m[5].via, {100, 250, 0}, down);
  EXPECT_EQ(m[5].via_name, "pArcMid");
  expect_target(m[5].target, {0, 150, 0}, down);
  // RelTool: -100 mm along the tool z (which points down), then 45 degrees about the tool z.
  expect_target(m[6].target, {0, 150, 100}, down * axis_rotation(2, 45 * kDegree));

  const double ori = 500 * kRadiansPerDegree;
  EXPECT_EQ(m[0].speed.name, "v1000");
  EXPECT_EQ(m[0].speed.tcp_speed, 1.0);
  EXPECT_EQ(m[0].speed.orientation_speed, ori);
  EXPECT_EQ(m[0].speed.external_linear_speed, 5.0);
  EXPECT_EQ(m[0].speed.external_rotation_speed, 1000 * kRadiansPerDegree);
  EXPECT_EQ(m[1].speed.name, "vmax");  // the robot's own maximum: left unset
  EXPECT_FALSE(m[1].speed.tcp_speed.has_value());
  EXPECT_FALSE(m[1].speed.orientation_speed.has_value());
  EXPECT_EQ(m[2].speed.tcp_speed, 0.2);
  EXPECT_EQ(m[3].speed.name, "vBead");
  EXPECT_EQ(m[3].speed.tcp_speed, 0.08);
  EXPECT_EQ(m[3].speed.orientation_speed, 30 * kRadiansPerDegree);
  EXPECT_EQ(m[3].speed.external_linear_speed, 0.2);
  EXPECT_EQ(m[3].speed.external_rotation_speed, 15 * kRadiansPerDegree);
  EXPECT_EQ(m[6].speed.name, "v500");
  EXPECT_EQ(m[6].speed.tcp_speed, 0.65);  // \V:=650
  EXPECT_EQ(m[6].speed.orientation_speed, ori);

  for (const std::size_t i : {0, 2, 7}) {
    EXPECT_EQ(m[i].blend.kind, BlendKind::kExactStop) << i;
    EXPECT_EQ(m[i].blend.name, "fine") << i;
  }
  const auto expect_zone = [](const MotionBlend& blend, const char* name, double radius, double ori_radius, double ori_degrees) {
    EXPECT_EQ(blend.kind, BlendKind::kDistance);
    EXPECT_EQ(blend.name, name);
    EXPECT_EQ(blend.radius, radius);
    EXPECT_EQ(blend.orientation_radius, ori_radius);
    EXPECT_EQ(blend.orientation_angle, ori_degrees * kRadiansPerDegree);
  };
  expect_zone(m[1].blend, "z50", 0.05, 0.075, 7.5);
  expect_zone(m[3].blend, "zBead", 0.003, 0.0045, 0.45);
  expect_zone(m[5].blend, "z1", 0.001, 0.001, 0.1);
  expect_zone(m[6].blend, "z20", 0.025, 0.03, 3.0);  // \Z:=25

  ASSERT_EQ(program.warnings.size(), 4u);
  expect_warning(program.warnings[0], kSample, 22, "the optional argument \\NoEOffs of MoveAbsJ is not read");
  expect_warning(program.warnings[1], kSample, 25, "not read: SetDO doGlue, 1");
  expect_warning(program.warnings[2], kSample, 36, "not read: WaitTime 0.2");
  expect_warning(program.warnings[3], kSample, 27, "not read: SetDO doGlue, 0");
}

TEST(RapidFile, QuaternionIsWFirstAQuarterTurnAboutZMapsXToY) {
  const RobotProgram p = parse_rapid_module(module("", "MoveL " + robtarget("[1, 2, 3]", "[0.70710678, 0, 0, 0.70710678]") + ", v100, fine, tool0;\n"));
  const CartesianTarget& target = cartesian(p.motions.at(0).target);
  expect_vector_near(target.R_BT * Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY(), 1e-15);
  EXPECT_EQ(target.p_BT, Eigen::Vector3d(0.001, 0.002, 0.003));
}

TEST(RapidFile, AssignmentsArraysParametersAndControlFlow) {
  const std::string data =
      "  VAR robtarget p := " + robtarget("[100, 0, 300]") + ";\n"
      "  CONST robtarget path{2} := [" + robtarget("[0, 0, 0]") + ", " + robtarget("[10, 0, 0]") + "];\n";
  const std::string body =
      "  VAR num height := 20;\n"                              // 5
      "  p := Offs(p, 10, 0, 0);\n"                            // 6
      "  p.trans.z := p.trans.z + height;\n"                   // 7
      "  MoveJ p, v100, z10, tool0;\n"                         // 8
      "  WHILE TRUE DO\n"                                      // 9
      "    IF DInput(di1) = 1 MoveL path{2}, v100, fine, tool0;\n"  // 10
      "    go path{1} \\dz:=5;\n"                              // 11
      "  ENDWHILE\n"
      "ERROR\n"                                                // 13
      "  RETRY;\n";
  const std::string routine =
      "PROC go(robtarget t, \\num dz)\n"
      "  MoveL Offs(t, 0, 0, dz), v100, fine, tool0;\n"
      "ENDPROC\n";
  const std::string text = "MODULE m\n" + data + "PROC main()\n" + body + "ENDPROC\n" + routine + "ENDMODULE\n";
  const RobotProgram p = parse_rapid_module(text);
  ASSERT_EQ(p.motions.size(), 3u);
  EXPECT_EQ(cartesian(p.motions[0].target).p_BT, Eigen::Vector3d(0.11, 0, 0.32));
  EXPECT_EQ(p.motions[1].line, 10);
  EXPECT_EQ(cartesian(p.motions[1].target).p_BT, Eigen::Vector3d(0.01, 0, 0));
  EXPECT_EQ(p.motions[2].line, 17);
  EXPECT_EQ(cartesian(p.motions[2].target).p_BT, Eigen::Vector3d(0, 0, 0.005));
  ASSERT_EQ(p.warnings.size(), 3u);
  expect_warning(p.warnings[0], "t.mod", 9,
                 "control flow not evaluated: WHILE TRUE DO (the statements inside are read once, in order)");
  expect_warning(p.warnings[1], "t.mod", 10,
                 "control flow not evaluated: IF DInput(di1)=1 MoveL path{2}, v100, fine, tool0 (the statement is "
                 "read as if the condition held)");
  expect_warning(p.warnings[2], "t.mod", 13, "not read: the ERROR handler of main (lines 13 to 15)");
}

TEST(RapidFile, WithoutMainTheFirstProcIsTheProgram) {
  const RobotProgram p = parse_rapid_module("MODULE m\nPROC first()\n  MoveAbsJ [[0, 0, 0, 0, 90, 0], " + kUnused +
                               "], v100, fine, tool0;\nENDPROC\nENDMODULE\n");
  EXPECT_EQ(p.name, "first");
  ASSERT_EQ(p.motions.size(), 1u);
  EXPECT_EQ(joints(p.motions[0].target), vector6(0, 0, 0, 0, 90 * kDegree, 0));
  ASSERT_EQ(p.warnings.size(), 1u);
  expect_warning(p.warnings[0], "t.mod", 2, "no PROC main: the first PROC first is read as the program");
}

TEST(RapidFile, RejectsUnreadableDataNamingIt) {
  expect_rapid_error(module("", "MoveL p99, v100, fine, tool0;\n"), 3,
               "expected a robtarget the reader can compute for the target of MoveL, found p99, which is declared "
               "nowhere in the program");
  expect_rapid_error(module("CONST robtarget p := [[0, 0, 0], [1, 0, 0, 0], [0, 0, 0, 0]];\n", ""), 2,
               "expected a robtarget [trans, rot, robconf, extax] for p, found an aggregate of 3 items");
  expect_rapid_error(module("", "MoveL " + robtarget("[0, 0, 0]", "[1, 0, 0, 0.5]") + ", v100, fine, tool0;\n"), 3,
               "expected a unit quaternion (norm 1 within 1e-3) in the robtarget of the target of MoveL, found norm 1.11803");
  expect_rapid_error(module("PERS tooldata t := [FALSE, [[0, 0, 0], [1, 0, 0, 0]], [1, [0, 0, 1], [1, 0, 0, 0], 0, 0, 0]];\n",
                      "MoveL " + robtarget("[0, 0, 0]") + ", v100, fine, t;\n"),
               4, "expected a robot-held tool (robhold TRUE) for the tool of MoveL; a stationary tool is not read, found robhold FALSE");
  expect_rapid_error(module("PERS wobjdata w := [TRUE, TRUE, \"\", [[0, 0, 0], [1, 0, 0, 0]], [[0, 0, 0], [1, 0, 0, 0]]];\n",
                      "MoveL " + robtarget("[0, 0, 0]") + ", v100, fine, tool0\\WObj:=w;\n"),
               4, "expected a fixed work object (robhold FALSE) for the work object of MoveL; a robot-held one is not read, found robhold TRUE");
  expect_rapid_error(module("", "MoveL Offs(CRobT(), 0, 0, 10), v100, fine, tool0;\n"), 3,
               "expected a robtarget the reader can compute for the target of MoveL, found CRobT(), the current "
               "position, which is not known before the run");
  expect_rapid_error(module("", "MoveL " + robtarget("[0, 0, 0]") + ", v100, zz, tool0;\n"), 3,
               "expected a zonedata the reader can compute for the zone of MoveL, found zz, which is declared nowhere in the program");
}

TEST(RapidFile, AnUnknownPartOfARobtargetIsNamedNotRead) {
  // Found by fuzz/rapid_fuzzer: Offs() read the parts of a robtarget whose rotation was unknown.
  const std::string data = "VAR robtarget p := [[100, 0, 300], -[1, 0, 0, 0], [0, 0, 0, 0], " + kUnused + "];\n";
  const std::string found = "'-' before an aggregate of 4 items (not evaluated)";
  expect_rapid_error(module(data, "MoveL Offs(p, 10, 0, 0), v100, fine, tool0;\n"), 4,
               "expected a robtarget the reader can compute for the target of MoveL, found " + found);
  expect_rapid_error(module(data, "MoveL p, v100, fine, tool0;\n"), 4,
               "expected a robtarget the reader can compute for the target of MoveL, found " + found);
  expect_rapid_error(module("", "MoveL " + robtarget("[0, 0, 0]") + ", [100, 500, x, 1000], fine, tool0;\n"), 3,
               "expected a speeddata the reader can compute for the speed of MoveL, found x, which is declared nowhere in the program");
}

TEST(RapidFile, RejectsMalformedProgramsNamingFileLineAndExpectation) {
  expect_rapid_error(module("", "MoveLDO p, v100, fine, tool0, do1, 1;\n"), 3,
               "expected a motion instruction the reader reads (MoveAbsJ, MoveJ, MoveL, MoveC), found 'MoveLDO'");
  expect_rapid_error("MODULE m\nPROC main()\n  MoveL p, v100, fine, tool0\nENDPROC\nENDMODULE\n", 6,
               "expected ';' ending the statement of line 3, found end of file");
  expect_rapid_error("PROC main()\nENDPROC\n", 1, "expected MODULE (RAPID code lives in modules), found 'PROC'");
  expect_rapid_error("MODULE m\nPROC main()\n", 3, "expected ENDPROC closing the PROC main of line 2, found end of file");
  expect_rapid_error("MODULE m\nPROC main()\nENDFUNC\nENDMODULE\n", 3, "expected ENDPROC closing the PROC main, found 'ENDFUNC'");
  expect_rapid_error(module("", "MoveL p, v100, fine;\n"), 3, "expected 4 arguments for MoveL (ToPoint, Speed, Zone, Tool), found 3");
  expect_rapid_error(module("", "MoveL p, v100, fine, tool0\\Foo:=1;\n"), 3,
               "expected an optional argument of MoveL (\\V, \\T, \\Z, \\WObj, \\Conc, \\ID, \\Inpos, \\TLoad, \\Corr, "
               "\\NoEOffs), found \\Foo");
  expect_rapid_error("MODULE m\nCONST num x := 1;\nENDMODULE\n", 4, "expected a PROC (the program) in the module, found none");
  expect_rapid_error("MODULE m\n  x := 1;\nENDMODULE\n", 2,
               "expected a data declaration, PROC, FUNC, TRAP or ENDMODULE in the module, found 'x'");
  expect_rapid_error(module("", "MoveL [[0, 0, 0], [1, 0, 0, 0]], v100, fine, tool0;\n"), 3,
               "expected a robtarget [trans, rot, robconf, extax] for the target of MoveL, found an aggregate of 2 items");
  expect_rapid_error(module("", "MoveL " + robtarget("[0, 0, 0]") + ", v100\\V:=-5, fine, tool0;\n"), 3,
               "expected a non-negative num for \\V of MoveL, found -5");
  expect_rapid_error(module("", "IF a IF b MoveL p, v100, fine, tool0;\n"), 3,
               "expected a statement after the IF condition (a compact IF holds one simple statement), found 'IF'");
  expect_rapid_error(module("", "MoveL p q, v100, fine, tool0;\n"), 3, "expected ',' after the argument, found 'q'");
  expect_rapid_error("MODULE m\nPROC main()\n  main;\nENDPROC\nENDMODULE\n", 3,
               "expected calls nested at most 32 deep (recursion is not evaluated), found a call of main nested deeper");
}

}  // namespace
}  // namespace grpvss::io

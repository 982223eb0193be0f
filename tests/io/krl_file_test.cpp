/// The KUKA KRL reader: the palletizing sample (.src + .dat + $config.dat) read into exact
/// motions, the warnings, inline-form data, and rejected input with file, line and message.

#include "grpvss/io/krl_file.hpp"

#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "grpvss/io/units.hpp"
#include "io/program_references.hpp"
#include "support/input_error_expectations.hpp"
#include "support/text_files.hpp"

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
using grpvss::testing::krl_reference;
using grpvss::testing::vector6;

const std::string kFolder = std::string(GRPVSS_SOURCE_DIR) + "/data/programs/";

RobotProgram parse_krl_text(const std::string& src, const std::string& dat = {}) {
  std::vector<KrlDataText> data;
  if (!dat.empty()) data.push_back({"t.dat", dat});
  return parse_krl(src, "t.src", data);
}

void expect_krl_error(const std::string& src, const std::string& dat, const std::string& file, int line,
                  const std::string& message) {
  expect_input_error([&] { parse_krl_text(src, dat); }, file, line, file + ":" + std::to_string(line) + ": " + message);
}

/// The program text with `body` inside DEF t() ... END (body lines start at line 2).
std::string program(const std::string& body) { return "DEF t()\n" + body + "END\n"; }

/// A KRL POS as the test expects it: mm and degrees to m and a rotation matrix by hand.
void expect_pos(const CartesianTarget& target, double x, double y, double z, double a, double b, double c) {
  expect_vector_near(target.p_BT, {x / 1000, y / 1000, z / 1000}, 0.0);
  expect_matrix_near(target.R_BT.toRotationMatrix(), krl_reference(a * kDegree, b * kDegree, c * kDegree), 1e-15);
}

void expect_bits(const CartesianTarget& target, std::optional<int> status, std::optional<int> turn) {
  const auto* bits = std::get_if<KrlStatusTurn>(&target.configuration);
  ASSERT_NE(bits, nullptr);
  EXPECT_EQ(bits->status, status);
  EXPECT_EQ(bits->turn, turn);
}

TEST(KrlFile, ReadsThePalletizingSampleWithItsDataFiles) {
  const RobotProgram program = read_krl_file(kFolder + "kr_palletize.src");
  EXPECT_EQ(program.language, ProgramLanguage::kKrl);
  EXPECT_EQ(program.name, "kr_palletize");
  EXPECT_EQ(program.files, (std::vector<std::string>{kFolder + "kr_palletize.src", kFolder + "$config.dat",
                                                     kFolder + "kr_palletize.dat"}));
  ASSERT_EQ(program.motions.size(), 9u);
  const auto& m = program.motions;

  const int lines[] = {28, 29, 30, 31, 34, 35, 46, 48, 38};
  const MotionKind kinds[] = {MotionKind::kJoint,  MotionKind::kJoint,    MotionKind::kLinear,
                              MotionKind::kLinear, MotionKind::kLinear,   MotionKind::kCircular,
                              MotionKind::kLinear, MotionKind::kLinear,   MotionKind::kJoint};
  const char* names[] = {"XHOME", "XP1", "XP2", "", "XP2", "XP3", "down", "XP3", ""};
  // $TOOL = TOOL_DATA[1] = {Z 230}; $BASE = BASE_DATA[2] = {X 1200, Z 100, A 90}.
  const Eigen::Matrix3d R_RB = axis_rotation(2, 90 * kDegree);
  for (std::size_t i = 0; i < m.size(); ++i) {
    EXPECT_EQ(m[i].line, lines[i]) << i;
    EXPECT_EQ(m[i].kind, kinds[i]) << i;
    EXPECT_EQ(m[i].target_name, names[i]) << i;
    EXPECT_EQ(m[i].file, kFolder + "kr_palletize.src") << i;
    EXPECT_EQ(m[i].tool_name, "TOOL_DATA[1]") << i;
    EXPECT_EQ(m[i].X_FT.translation(), Eigen::Vector3d(0, 0, 0.23)) << i;
    EXPECT_EQ(m[i].X_FT.linear(), Eigen::Matrix3d::Identity()) << i;
    EXPECT_EQ(m[i].base_name, "BASE_DATA[2]") << i;
    EXPECT_EQ(m[i].X_RB.translation(), Eigen::Vector3d(1.2, 0, 0.1)) << i;
    expect_matrix_near(m[i].X_RB.linear(), R_RB, 1e-15);
    // BAS(#VEL_PTP, 50) then $VEL_AXIS[6] = 80; $VEL.CP 0.5 until line 36 sets 0.2.
    const std::vector<std::optional<double>> axes = {50.0, 50.0, 50.0, 50.0, 50.0, 80.0};
    EXPECT_EQ(m[i].speed.joint_speed_percent, axes) << i;
    EXPECT_TRUE(m[i].speed.joint_acceleration_percent.empty()) << i;
    EXPECT_EQ(m[i].speed.tcp_speed, i < 6 ? 0.5 : 0.2) << i;
    EXPECT_EQ(m[i].speed.tcp_acceleration, 2.0) << i;
    EXPECT_FALSE(m[i].speed.orientation_speed.has_value()) << i;
  }
  EXPECT_EQ(joints(m[0].target), vector6(0, -90 * kDegree, 90 * kDegree, 0, 45 * kDegree, 0));
  expect_pos(cartesian(m[1].target), 600, -250, 400, 0, 90, 0);
  expect_bits(cartesian(m[1].target), 2, 35);
  expect_pos(cartesian(m[2].target), 600, -250, 120, 90, 0, 180);
  expect_bits(cartesian(m[2].target), 2, 34);  // 'B010', 'B100010'
  expect_pos(cartesian(m[3].target), 600, -250, 50, 90, 0, 180);  // {Z 50} completed from XP2
  expect_bits(cartesian(m[3].target), std::nullopt, std::nullopt);
  expect_pos(cartesian(m[4].target), 600, -250, 120, 90, 0, 180);
  expect_pos(cartesian(*m[5].via), 300, 0, 500, 90, 0, 180);
  EXPECT_EQ(m[5].via_name, "XAUX");
  expect_pos(cartesian(m[5].target), 0, 450, 300, -90, 0, 180);
  EXPECT_FALSE(m[5].circular_angle.has_value());
  expect_pos(cartesian(m[6].target), 0, 450, 250, -90, 0, 180);  // down.Z = XP3.Z - depth (50)
  expect_bits(cartesian(m[6].target), 2, 2);
  expect_pos(cartesian(m[7].target), 0, 450, 300, -90, 0, 180);
  EXPECT_EQ(joints(m[8].target), vector6(0, -90 * kDegree, 90 * kDegree, 0, 0, 0));

  // $APO.CPTP 40 (%), $APO.CDIS 20 mm.
  EXPECT_EQ(m[1].blend.kind, BlendKind::kPtpPercent);
  EXPECT_EQ(m[1].blend.ptp_percent, 40.0);
  EXPECT_EQ(m[1].blend.name, "C_PTP");
  for (const std::size_t i : {2, 4, 5}) {
    EXPECT_EQ(m[i].blend.kind, BlendKind::kDistance) << i;
    EXPECT_EQ(m[i].blend.radius, 0.02) << i;
    EXPECT_EQ(m[i].blend.name, "C_DIS") << i;
  }
  for (const std::size_t i : {0, 3, 6, 7, 8}) EXPECT_EQ(m[i].blend.kind, BlendKind::kExactStop) << i;

  const std::string src = kFolder + "kr_palletize.src";
  ASSERT_EQ(program.warnings.size(), 7u);
  expect_warning(program.warnings[0], kFolder + "$config.dat", 8, "not read: SIGNAL GRIPPER_CLOSED $OUT[1]");
  expect_warning(program.warnings[1], kFolder + "kr_palletize.dat", 8, "not read: EXT BAS(BAS_COMMAND: IN, REAL: IN)");
  expect_warning(program.warnings[2], src, 8, "not read: GLOBAL INTERRUPT DECL 3 WHEN $STOPMESS == TRUE DO IR_STOPM()");
  expect_warning(program.warnings[3], src, 9, "not read: INTERRUPT ON 3");
  expect_warning(program.warnings[4], src, 32, "not read: $OUT[1]=TRUE");
  expect_warning(program.warnings[5], src, 33, "not read: WAIT SEC 0.5");
  expect_warning(program.warnings[6], src, 47, "not read: $OUT[1]=FALSE");
}

TEST(KrlFile, AbcOf90MapsXToY) {
  const RobotProgram p = parse_krl_text(program("$TOOL = $NULLFRAME\n$BASE = $NULLFRAME\nLIN {X 1, Y 2, Z 3, A 90, B 0, C 0}\n"));
  const CartesianTarget& target = cartesian(p.motions.at(0).target);
  expect_vector_near(target.R_BT * Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY(), 1e-15);
  EXPECT_TRUE(p.warnings.empty());
}

TEST(KrlFile, ApproximationKindsTakeTheirApoValues) {
  const RobotProgram p = parse_krl_text(program(
      "$TOOL = {X 0, Y 0, Z 100, A 0, B 0, C 0}\n$BASE = $NULLFRAME\n"
      "$APO = {CDIS 5, CPTP 30, CORI 10, CVEL 60}\n$VEL = {CP 1.5, ORI1 200, ORI2 100}\n"
      "$ACC.ORI1 = 400\n$ACC_AXIS[2] = 70\n"
      "PTP {X 500, Y 0, Z 500, A 0, B 90, C 0} C_DIS\n"  // 8
      "LIN {X 400} C_ORI\n"                              // 9
      "LIN {X 300} C_VEL\n"                              // 10
      "CIRC {X 350, Y 50}, {X 400, Y 0}, CA 90 C_DIS\n"  // 11
      "BAS(#INITMOV, 0)\n"
      "LIN {X 500} C_DIS\n"));                           // 13
  ASSERT_EQ(p.motions.size(), 5u);
  const auto& m = p.motions;
  EXPECT_EQ(m[0].blend.kind, BlendKind::kDistance);
  EXPECT_EQ(m[0].blend.radius, 0.005);
  EXPECT_EQ(m[1].blend.kind, BlendKind::kOrientationAngle);
  EXPECT_EQ(m[1].blend.orientation_angle, 10 * kRadiansPerDegree);
  EXPECT_EQ(m[2].blend.kind, BlendKind::kVelocityPercent);
  EXPECT_EQ(m[2].blend.velocity_percent, 60.0);
  EXPECT_EQ(m[3].circular_angle, 90 * kRadiansPerDegree);
  expect_pos(cartesian(*m[3].via), 350, 50, 500, 0, 90, 0);
  expect_pos(cartesian(m[3].target), 400, 0, 500, 0, 90, 0);
  EXPECT_EQ(m[0].speed.tcp_speed, 1.5);
  EXPECT_EQ(m[0].speed.orientation_speed, 200 * kRadiansPerDegree);
  EXPECT_EQ(m[0].speed.orientation_speed_2, 100 * kRadiansPerDegree);
  EXPECT_EQ(m[0].speed.orientation_acceleration, 400 * kRadiansPerDegree);
  const std::vector<std::optional<double>> acc = {std::nullopt, 70.0, std::nullopt, std::nullopt, std::nullopt, std::nullopt};
  EXPECT_EQ(m[0].speed.joint_acceleration_percent, acc);
  // BAS(#INITMOV): speeds and approximation back to the controller's defaults (unset).
  EXPECT_EQ(m[4].blend.kind, BlendKind::kDistance);
  EXPECT_FALSE(m[4].blend.radius.has_value());
  EXPECT_FALSE(m[4].speed.tcp_speed.has_value());
  EXPECT_TRUE(m[4].speed.joint_acceleration_percent.empty());
  EXPECT_EQ(m[4].X_FT.translation(), Eigen::Vector3d(0, 0, 0.1));  // $TOOL stays
}

TEST(KrlFile, InlineFormsTakeToolAndBaseFromFdat) {
  const std::string dat =
      "DEFDAT t\n"
      "DECL E6POS XP1={X 100,Y 200,Z 300,A 0,B 0,C 0,S 6,T 27,E1 500,E2 0}\n"
      "DECL FDAT FP1={TOOL_NO 2,BASE_NO 0,IPO_FRAME #BASE,POINT2[] \" \",TQ_STATE FALSE}\n"
      "DECL PDAT PPDAT1={VEL 100,ACC 100,APO_DIST 100,APO_MODE #CDIS}\n"
      "TOOL_DATA[2]={X 10,Y 0,Z 150,A 0,B 0,C 0}\n"
      "ENDDAT\n";
  const RobotProgram p = parse_krl_text(program(
      ";FOLD PTP P1 Vel=75 % PDAT1 Tool[2] Base[0];%{PE}\n"  // 2
      "$BWDSTART=FALSE\n"                                     // 3
      "PDAT_ACT=PPDAT1\n"
      "FDAT_ACT=FP1\n"
      "BAS(#PTP_PARAMS,75)\n"                                 // 6
      "PTP XP1\n"                                             // 7
      ";ENDFOLD\n"
      "PTP $AXIS_ACT\n"                                       // 9
      "LIN XP1 WITH $VEL.CP = 0.1\n"),                        // 10
      dat);
  ASSERT_EQ(p.motions.size(), 2u);
  const ProgramMotion& m = p.motions[0];
  EXPECT_EQ(m.tool_name, "TOOL_DATA[2]");
  EXPECT_EQ(m.X_FT.translation(), Eigen::Vector3d(0.01, 0, 0.15));
  EXPECT_EQ(m.base_name, "$NULLFRAME");
  EXPECT_TRUE(m.X_RB.isApprox(Eigen::Isometry3d::Identity(), 0.0));
  const std::vector<std::optional<double>> axes(6, 75.0);
  EXPECT_EQ(m.speed.joint_speed_percent, axes);
  expect_bits(cartesian(m.target), 6, 27);
  ASSERT_EQ(p.warnings.size(), 6u);
  expect_warning(p.warnings[0], "t.src", 3, "not read: $BWDSTART=FALSE");
  expect_warning(p.warnings[1], "t.src", 6,
                 "partly read: BAS(#PTP_PARAMS, 75) (the velocity and FDAT_ACT's tool and base are read; "
                 "PDAT_ACT's acceleration and approximation are not)");
  expect_warning(p.warnings[2], "t.src", 7, "external axis not read: E1 = 500");
  expect_warning(p.warnings[3], "t.src", 9,
                 "not read: PTP $AXIS_ACT (a move to the current position, which is not known before the run)");
  expect_warning(p.warnings[4], "t.src", 10, "not read: the WITH clause of LIN XP1 WITH $VEL.CP=0.1");
  expect_warning(p.warnings[5], "t.src", 10, "external axis not read: E1 = 500");
}

TEST(KrlFile, ReadsConfigDatStyleData) {
  const std::string config =
      "DEFDAT  $CONFIG PUBLIC\n"                                                   // 1
      "ENUM SW_ONOFF ON,OFF\n"                                                     // 2
      "STRUC MY_T INT A, REAL B\n"                                                 // 3
      "DECL CHAR TOOL_NAME[16,24]\n"
      "TOOL_NAME[1,]=\"gripper\"\n"
      "DECL TOOL_TYPE TOOL_TYPE[16]\n"
      "TOOL_TYPE[1]=#NONE\n"
      "DECL LOAD LOAD_DATA[16]\n"
      "LOAD_DATA[1]={M 12.5,CM {X 0.0,Y 0.0,Z 80.0,A 0.0,B 0.0,C 0.0},J {X 0.1,Y 0.1,Z 0.05}}\n"
      "DECL FRAME TOOL_DATA[16]\n"
      "TOOL_DATA[1]={X 0.0,Y 0.0,Z 180.0,A 0.0,B 0.0,C 0.0}\n"
      "DECL E6AXIS XHOME={A1 0.0,A2 -90.0,A3 90.0,A4 0.0,A5 0.0,A6 0.0,E1 0.0,E2 0.0}\n"
      "ENDDAT\n";
  const RobotProgram p = parse_krl(program("$TOOL = TOOL_DATA[1]\nPTP XHOME\n"), "t.src", {{"$config.dat", config}});
  ASSERT_EQ(p.motions.size(), 1u);
  EXPECT_EQ(p.motions[0].X_FT.translation(), Eigen::Vector3d(0, 0, 0.18));
  EXPECT_EQ(joints(p.motions[0].target), vector6(0, -90 * kDegree, 90 * kDegree, 0, 0, 0));
  ASSERT_EQ(p.warnings.size(), 2u);
  expect_warning(p.warnings[0], "$config.dat", 2, "not read: ENUM SW_ONOFF ON, OFF");
  expect_warning(p.warnings[1], "$config.dat", 3, "not read: STRUC MY_T INT A, REAL B");
}

TEST(KrlFile, GeometricOperatorComposesFrames) {
  const RobotProgram p = parse_krl_text(program(
      "$TOOL = $NULLFRAME\n"
      "$BASE = BASE_DATA[1] : {X 100, Y 0, Z 0, A 0, B 0, C 0}\n"
      "LIN {X 0, Y 0, Z 0, A 0, B 0, C 0}\n"),
      "BASE_DATA[1]={X 1000,Y 0,Z 0,A 90,B 0,C 0}\n");
  const ProgramMotion& m = p.motions.at(0);
  EXPECT_EQ(m.base_name, "BASE_DATA[1]: {X 100, Y 0, Z 0, A 0, B 0, C 0}");
  expect_vector_near(m.X_RB.translation(), {1.0, 0.1, 0.0}, 1e-15);  // (100, 0) turned by 90 degrees
  expect_matrix_near(m.X_RB.linear(), axis_rotation(2, 90 * kDegree), 1e-15);
}

TEST(KrlFile, WarnsWhenToolOrBaseIsNotSetAndLogicIsNotEvaluated) {
  const RobotProgram p = parse_krl_text(program("IF $IN[1] THEN\nLIN {X 1, Y 2, Z 3, A 0, B 0, C 0}\nENDIF\nsub()\n"));
  ASSERT_EQ(p.motions.size(), 1u);
  EXPECT_EQ(p.motions[0].tool_name, "$NULLFRAME (not set)");
  ASSERT_EQ(p.warnings.size(), 4u);
  expect_warning(p.warnings[0], "t.src", 2,
                 "control flow not evaluated: IF $IN[1] THEN (the statements inside are read once, in order)");
  expect_warning(p.warnings[1], "t.src", 3,
                 "$TOOL is not set before this motion: the flange ($NULLFRAME) is taken (the controller keeps the $TOOL it had)");
  expect_warning(p.warnings[2], "t.src", 3,
                 "$BASE is not set before this motion: the robot base ($NULLFRAME, $WORLD = $ROBROOT) is taken");
  expect_warning(p.warnings[3], "t.src", 5, "not read: sub()");
}

TEST(KrlFile, RejectsUndeclaredPointsToolsAndBasesNamingThem) {
  const std::string nowhere = ", which is declared nowhere (neither in the program nor in its data files)";
  expect_krl_error(program("PTP XP9\n"), "", "t.src", 2, "expected a target the reader can compute for PTP, found XP9" + nowhere);
  expect_krl_error(program("$TOOL = TOOL_DATA[3]\n"), "", "t.src", 2,
               "expected a FRAME the reader can compute for $TOOL, found TOOL_DATA[3]" + nowhere);
  expect_krl_error(program("BAS(#BASE, 4)\n"), "", "t.src", 2,
               "expected a FRAME the reader can compute for $BASE, found BASE_DATA[4]" + nowhere);
  expect_krl_error(program("PTP XP1\n"), "DEFDAT t\nDECL E6POS XP1\nENDDAT\n", "t.src", 2,
               "expected a target the reader can compute for PTP, found XP1, declared without a value at t.dat:2");
  expect_krl_error(program("BAS(#PTP_PARAMS, 100)\n"), "", "t.src", 2,
               "expected FDAT_ACT (the tool and base of BAS(#PTP_PARAMS)) the reader can compute, found FDAT_ACT" + nowhere);
}

TEST(KrlFile, RejectsMalformedProgramsNamingFileLineAndExpectation) {
  expect_krl_error(program("LIN {X 100}\n"), "", "t.src", 2,
               "expected a complete POS (X, Y, Z, A, B, C) for LIN (a partial one is completed only from the previous "
               "target of the same kind, tool and base), found no Y");
  expect_krl_error(program("LIN {A1 0, A2 0, A3 0, A4 0, A5 0, A6 0}\n"), "", "t.src", 2,
               "expected a Cartesian target (POS, E6POS or FRAME) for LIN, found an AXIS");
  expect_krl_error(program("PTP {A1 0, X 1}\n"), "", "t.src", 2,
               "expected components A1..A6 (AXIS) or X, Y, Z, A, B, C (POS) for PTP, found both kinds");
  expect_krl_error(program("SPLINE\n"), "", "t.src", 2, "expected a motion the reader reads (PTP, LIN, CIRC), found 'SPLINE'");
  expect_krl_error("DEF t()\nPTP XP1\n", "", "t.src", 3, "expected END closing the DEF t of line 1, found end of file");
  expect_krl_error("PTP XP1\n", "", "t.src", 1, "expected DEF or DEFFCT (a .src holds routines only), found 'PTP'");
  expect_krl_error(program("$BASE = $NULLFRAME\nLIN {X 1, Y 2, Z 3, A 0, B 0, C 0} C_PTP\n"), "", "t.src", 3,
               "expected C_DIS, C_ORI or C_VEL after LIN or CIRC, found C_PTP");
  expect_krl_error(program("$VEL_AXIS[1] = 150\n"), "", "t.src", 2, "expected a percentage in (0, 100] for $VEL_AXIS[1], found 150");
  expect_krl_error(program("$IPO_MODE = #TCP\n"), "", "t.src", 2,
               "expected $IPO_MODE = #BASE (a robot-held tool; an external TCP is not read), found #TCP");
  expect_krl_error(program("PTP {X 1, Y 2, Z 3, A 0, B 0, C 0, S 2.5}\n"), "", "t.src", 2,
               "expected a non-negative integer S for PTP, found 2.5");
  expect_krl_error(program("PTP {A1 0\n"), "", "t.src", 2, "expected a closing '}', found end of statement");
  expect_krl_error(program("PTP XP1\n"), "DECL E6POS XP1={X 1,, Y 2}\n", "t.dat", 1, "expected a component name, found ','");
  expect_krl_error(program("CIRC {X 1, Y 2, Z 3, A 0, B 0, C 0}\n"), "", "t.src", 2,
               "expected ',' between the auxiliary point and the target of CIRC, found end of statement");
  expect_krl_error(program("sub()\n") + "DEF sub()\nsub()\nEND\n", "", "t.src", 5,
               "expected calls nested at most 32 deep (recursion is not evaluated), found a call of sub nested deeper");
  // inf - inf is NaN: refused before any conversion to an integer.
  expect_krl_error(program("BAS(#TOOL, 1E308*10 - 1E308*10)\n"), "", "t.src", 2,
               "expected a tool or base number for BAS(#TOOL, n), found a result that is not a finite number");
}

TEST(KrlFile, FindsTheDatBesideTheSrcIgnoringCaseAndNeedsItOnlyWhenUsed) {
  const std::string folder = test::make_temporary_directory("krl-dat");
  {
    std::ofstream(folder + "/PICK.SRC") << "DEF pick()\nPTP XP1\nEND\n";
    std::ofstream(folder + "/pick.DAT") << "DEFDAT PICK\nDECL AXIS XP1={A1 10,A2 0,A3 0,A4 0,A5 0,A6 0}\nENDDAT\n";
    std::ofstream(folder + "/alone.src") << "DEF alone()\nPTP {A1 0, A2 0, A3 0, A4 0, A5 0, A6 0}\nEND\n";
    std::ofstream(folder + "/needs.src") << "DEF needs()\nPTP XP1\nEND\n";
  }
  const RobotProgram pick = read_krl_file(folder + "/PICK.SRC");
  EXPECT_EQ(pick.files, (std::vector<std::string>{folder + "/PICK.SRC", folder + "/pick.DAT"}));
  EXPECT_EQ(joints(pick.motions.at(0).target), vector6(10 * kDegree, 0, 0, 0, 0, 0));
  EXPECT_EQ(read_krl_file(folder + "/alone.src").motions.size(), 1u);
  expect_input_error([&] { read_krl_file(folder + "/needs.src"); }, folder + "/needs.src", 2,
                     folder + "/needs.src:2: expected a target the reader can compute for PTP, found XP1, which is "
                              "declared nowhere (neither in the program nor in its data files)");
  std::filesystem::remove_all(folder);
}

}  // namespace
}  // namespace grpvss::io

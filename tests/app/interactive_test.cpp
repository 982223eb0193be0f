// Drives the interactive session (thesis Appendix A.2.2) with scripted answers: the running
// sample of the thesis, the end of input at every prompt, invalid answers, and the real CLI
// with piped stdin.
#include <sys/wait.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "grpvss/certify/verifier.hpp"
#include "grpvss/io/environment_file.hpp"
#include "grpvss/io/path_file.hpp"
#include "grpvss/io/robot_file.hpp"
#include "grpvss/motion/kinematics_adapter.hpp"
#include "grpvss/report/svg_render.hpp"
#include "grpvss/report/thesis_output.hpp"
#include "interactive/answer_parsing.hpp"
#include "interactive/session.hpp"
#include "support/text_files.hpp"

namespace grpvss::app::interactive {
namespace {

const std::string kDataDir = std::string(GRPVSS_SOURCE_DIR) + "/data";
const std::string kSample = kDataDir + "/ibm7545/";

struct Transcript {
  SessionEnd end = SessionEnd::kExitChosen;
  std::string out;
  ViewSettings view;
  int motions = 0;
};

std::string join_lines(const std::vector<std::string>& answers) {
  std::string text;
  for (const std::string& answer : answers) text += answer + "\n";
  return text;
}

Transcript run_session(const std::vector<std::string>& answers, const std::string& dir,
                       int max_invalid = 20) {
  std::istringstream in(join_lines(answers));
  std::ostringstream out;
  SessionSettings settings;
  settings.data_dir = kDataDir;
  settings.animation_dir = dir;
  settings.max_invalid_answers = max_invalid;
  Session session(in, out, settings);
  Transcript transcript;
  transcript.end = session.run();
  transcript.out = out.str();
  transcript.view = session.view();
  transcript.motions = session.motions_processed();
  return transcript;
}

/// Each of `lines` occurs in `text`, in this order.
::testing::AssertionResult appear_in_order(const std::string& text,
                                           const std::vector<std::string>& lines) {
  std::size_t at = 0;
  for (const std::string& line : lines) {
    const std::size_t found = text.find(line, at);
    if (found == std::string::npos) {
      return ::testing::AssertionFailure()
             << "missing (in order) \"" << line << "\" after offset " << at << " in:\n" << text;
    }
    at = found + line.size();
  }
  return ::testing::AssertionSuccess();
}

std::size_t count_of(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

/// `text` with the interference-point lines (x<TAB>y<TAB>z) of each step sorted. The library
/// lists the same points of a step in an order that varies between processes with the same
/// inputs (reported to the lead), so outputs are compared as step-wise point sets.
std::string with_sorted_points(const std::string& text) {
  std::string out;
  std::vector<std::string> block;
  const auto flush = [&] {
    std::sort(block.begin(), block.end());
    for (const std::string& line : block) out += line + "\n";
    block.clear();
  };
  for (const std::string& line : test::split_lines(text)) {
    if (line.find('\t') != std::string::npos) {
      block.push_back(line);
      continue;
    }
    flush();
    out += line + "\n";
  }
  flush();
  return out;
}

/// The thesis output text of an independent verification of the same inputs.
std::string independent_thesis_output(const std::string& path_file, double tolerance,
                                      const std::string& label, certify::Verdict* verdict) {
  const RobotModel robot = io::read_robot_file(kSample + "robot.txt");
  const Environment environment = io::read_environment_file(kSample + "environment.txt");
  const PathProgram program = io::read_path_file(path_file, robot);
  certify::SetupRequest options;
  options.tolerance = tolerance;
  options.path_label = label;
  const auto ik = motion::select_ik({}, robot, kSample + "robot.txt");
  const certify::VerificationRun run = certify::verify(
      robot, environment, program, motion::make_kinematics_access(robot, ik), certify::resolve_setup(options));
  *verdict = run.result.verdict;
  return report::render_thesis_output(run.result, robot);
}

// The running sample of A.2.2, answer by answer. Where the thesis omits the remaining joints
// ("for convenience, the values of the remaining joints have been omitted"), the script gives
// the joint values of the sample path file (data/ibm7545/path.txt).
std::vector<std::string> thesis_running_sample(const std::string& dir) {
  return {
      "1",                          // WHICH ROBOT: 1. IBM 7545 ROBOT
      "1",                          // PTP TRAJECTORY: 1. IDEAL TRAPEZOID FUNCTIONS
      kSample + "environment.txt",  // THE VERTICES OF THE OBSTACLES ... FILE
      "0.5",                        // ENTER THE TOLERANCE VALUE
      "y",                          // WANT TO CHANGE THE VIEW ANGLES ?
      "-75.,0.,85.,",               // ANGLEX, ANGLEY, ANGLEZ,
      "y",                          // WANT TO CHANGE THE SCALE AND SHIFT THE WINDOW ?
      "1.5,-20.,-10.,0.,",          // SCALE, SHIFTX, SHIFTY, SHIFTZ,
      "1",                          // THE PATH: 1. FROM DATA FILE
      kSample + "path.txt",         // ... STORED IN THE FILE ...
      "Y",                          // DO YOU WISH TO STORE THE RESULTS ... ?
      dir + "/OUT1",                // THE RESULTS WILL BE STORED IN A FILE NAMED
      "N",                          // (after PROCESSING) WANT TO CHANGE THE VIEW ANGLES ?
      "N",                          // WANT TO CHANGE THE SCALE AND SHIFT THE WINDOW ?
      "2",                          // MOTION IMAGE: anything but 1 = continuous
      "4",                          // MAIN MENU: 4. PERFORM ANOTHER MOTION
      "2",                          // THE PATH: 2. INTERACTIVELY INPUT ON THE SCREEN
      "1",                          // OPERATION: 1. PTP ... JOINT COORD. SYSTEM
      "250.,4.,",                   // joint 1 out of range (MAX 200): asked again
      "50.,4.,",                    // JOINT 1
      "50.,4.,",                    // JOINT 2
      "5.,0.3,",                    // JOINT 3 (prismatic)
      "50.,4.,",                    // JOINT 4
      "Y",                          // ARE THE INPUT DATA CORRECT ?
      "",                           // ANOTHER MOTION SEGMENT IN THIS PATH ? (default N)
      "n",                          // DO YOU WISH TO STORE THE RESULTS ... ?
      "N", "N", "2",                // view angles, scale/shift, continuous motion
      "4",                          // MAIN MENU: 4. PERFORM ANOTHER MOTION
      "2",                          // THE PATH: 2. INTERACTIVELY
      "2",                          // OPERATION: 2. PTP ... WORLD COORD. SYSTEM
      "0.0,20.0,6.0,",              // FINAL POSITION (X, Y, Z)
      "0.0,0.0,-1.,30.,",           // AXIS (KX,KY,KZ) AND KTHETA
      "4.0,", "4.0,", "0.3,", "4.0,",  // DESIRED JOINT VELOCITY OF JOINT 1..4
      "Y",                          // ARE THE INPUT DATA CORRECT ?
      "",                           // ANOTHER MOTION SEGMENT ? (default N)
      "",                           // STORE THE RESULTS ? (default Y)
      dir + "/OUT1",                // an existing name: refused, asked again
      dir + "/OUT2",
      "", "", "",                   // view angles (default N), scale (default N), continuous
      "4",                          // MAIN MENU: 4. PERFORM ANOTHER MOTION
      "2",                          // THE PATH: 2. INTERACTIVELY
      "3",                          // OPERATION: 3. CP STRAIGHT-LINE OPERATION
      "0.0,20.0,6.0,",              // FINAL POSITION
      "0.0,0.0,-1.,30.,",           // AXIS AND KTHETA
      "Y",                          // ARE THE INPUT DATA CORRECT ?
      "",                           // ANOTHER MOTION SEGMENT ?
      "n",                          // STORE THE RESULTS ?
      "N", "N", "2",
      "6",                          // MAIN MENU: 6. EXIT
  };
}

TEST(InteractiveSession, FollowsTheThesisRunningSample) {
  const std::string dir = test::make_temporary_directory("interactive-sample");
  const Transcript t = run_session(thesis_running_sample(dir), dir);
  // The picture shows the first colliding step of OUT1 (the report names it).
  const nlohmann::json out1 = nlohmann::json::parse(test::read_text_file(dir + "/OUT1.json"));
  ASSERT_TRUE(out1["collision_step"].is_number_integer());
  const int first_collision = out1["collision_step"].get<int>();
  EXPECT_EQ(t.end, SessionEnd::kExitChosen) << t.out;
  EXPECT_EQ(exit_code(t.end), 0);
  EXPECT_EQ(t.motions, 4) << t.out;
  EXPECT_TRUE(appear_in_order(
      t.out,
      {"WHICH ROBOT ARE YOU GOING TO SIMULATE ?\n1. IBM 7545 ROBOT\n2. OTHERS\n"
       "ENTER ONE OF THE OPTION NUMBERS\n",
       "ENTER THE WAY TO GENERATE THE PTP TRAJECTORY\n1. IDEAL TRAPEZOID FUNCTIONS\n",
       "THE VERTICES OF THE OBSTACLES IN THE WORKING\n", "ENTER THE TOLERANCE VALUE\n",
       "THE TOLERANCE VALUE = 0.50\n", "CURRENT CONFIGURATION (HOME)\n",
       "WANT TO CHANGE THE VIEW ANGLES ?\nENTER Y/N (DEFAULT = N)\n",
       "ENTER ANGLEX, ANGLEY, ANGLEZ,\n",
       "WANT TO CHANGE THE SCALE AND SHIFT THE WINDOW ?\nENTER Y/N (DEFAULT = N)\n",
       "ENTER SCALE, SHIFTX, SHIFTY, SHIFTZ,\n",
       "ENTER THE WAY YOU WANT TO INPUT THE PATH\n1. FROM DATA FILE\n"
       "2. INTERACTIVELY INPUT ON THE SCREEN\n",
       "DO YOU WISH TO STORE THE RESULTS OF THIS PATH\nIN A FILE ?\nENTER Y/N (DEFAULT = Y)\n",
       "MAKE SURE THE FILE YOU SPECIFIED DOES NOT EXIST\n", "PROCESSING\n", "verdict: ",
       "THE RESULTS ARE STORED IN " + dir + "/OUT1\n",
       "WHAT TYPE OF MOTION IMAGE DO YOU LIKE?\n",
       "THE PICTURE OF STEP " + std::to_string(first_collision) + " IN THIS VIEW IS IN " + dir +
           "/OUT1.svg\n",
       "THE REPORT OF THIS PATH (WITH THE SCENE) IS IN " + dir + "/OUT1.json\n",
       "ENTER ONE OF THE FOLLOWING OPTION NUMBERS\n1. SIMULATE ANOTHER ROBOT\n"
       "2. CHANGE THE ENVIRONMENT\n3. CHANGE THE TOLERANCE VALUE\n4. PERFORM ANOTHER MOTION\n"
       "5. SEE THE ANIMATION AGAIN\n6. EXIT\n",
       // Motion 2: PTP (JCS) typed; joint 1 out of range is asked again.
       "WHICH TYPE OF OPERATION FOR THIS MOTION SEGMENT ?\n"
       "1. PTP OPERATION SPECIFIED IN JOINT COORD. SYSTEM\n"
       "2. PTP OPERATION SPECIFIED IN WORLD COORD. SYSTEM\n3. CP STRAIGHT-LINE OPERATION\n",
       "ENTER THE JOINT VALUE OF JOINT 1 AT ENDING POINT\n"
       "MIN VALUE = 0.00 MAX VALUE = 200.00 HOME POSITION = 0.00\n"
       "AND THE DESIRED JOINT VELOCITY\nUSE A COMMA AFTER EACH DATA INCLUDING THE LAST ONE\n",
       "INVALID ANSWER: the joint value 250 is out of range (MIN 0.00, MAX 200.00); enter the "
       "values again\nENTER THE JOINT VALUE OF JOINT 1 AT ENDING POINT\n",
       "ENTER THE JOINT VALUE OF JOINT 2 AT ENDING POINT\n"
       "MIN VALUE = 0.00 MAX VALUE = 135.00 HOME POSITION = 0.00\n",
       "ENTER THE JOINT VALUE OF JOINT 3 AT ENDING POINT\n"
       "MIN VALUE = 0.00 MAX VALUE = 9.80 HOME POSITION = 0.00\n",
       "ENTER THE JOINT VALUE OF JOINT 4 AT ENDING POINT\n"
       "MIN VALUE = -180.00 MAX VALUE = 180.00 HOME POSITION = 0.00\n",
       "ARE THE INPUT DATA CORRECT ?\nENTER Y/N (DEFAULT = Y)\n", "PROCESSING\n",
       // Motion 3: PTP (WCS) typed; the existing OUT1 is refused.
       "ENTER THE FINAL POSITION (X, Y, Z) OF THE END EFFECTOR\n",
       "ENTER THE AXIS (KX,KY,KZ) ABOUT WHICH THE\nORIENTATION OF END EFFECTOR CHANGES\n"
       "AND THE CORRESPONDING CHANGING ANGLE (KTHETA) IN DEGREES\n",
       "ENTER THE DESIRED JOINT VELOCITY OF JOINT 1\nFOR REVOLUTE JOINTS, THE UNIT IS DEGREE/SEC\n",
       "ENTER THE DESIRED JOINT VELOCITY OF JOINT 3\n"
       "FOR PRISMATIC JOINTS, THE UNIT IS LENGTH UNITS/SEC\n",
       "INVALID ANSWER: the file " + dir + "/OUT1 already exists; enter another name\n",
       "THE RESULTS ARE STORED IN " + dir + "/OUT2\n",
       "THE TYPED PATH IS STORED IN " + dir + "/OUT2.path.txt\n",
       "THE REPORT OF THIS PATH (WITH THE SCENE) IS IN " + dir + "/OUT2.json\n",
       // Motion 4: CP typed, results not stored: the animation gets a numbered name.
       // From home the line leaves the workspace at once: thesis error 5, no step to draw.
       "3. CP STRAIGHT-LINE OPERATION\n", "PROCESSING\n", "verdict: ERROR\n",
       "error 5 (segment 1, step 0): Unreachable intermediate point was encountered in the "
       "motion segment 1 in the input file.",
       "THE REPORT OF THIS PATH (WITH THE SCENE) IS IN " + dir + "/grpvss-motion-4.json\n",
       "6. EXIT\n", "GRPVSS SESSION ENDED\n"}));
  EXPECT_EQ(count_of(t.out, "PROCESSING\n"), 4u);
  EXPECT_EQ(count_of(t.out, "INVALID ANSWER"), 2u) << t.out;

  // The view changes are stored for the animation.
  EXPECT_EQ(t.view.angles_deg, (std::array<double, 3>{-75.0, 0.0, 85.0}));
  EXPECT_EQ(t.view.scale, 1.5);
  EXPECT_EQ(t.view.shift, (std::array<double, 3>{-20.0, -10.0, 0.0}));
  EXPECT_FALSE(t.view.stepping);

  // OUT1 is exactly what an independent verification of the same inputs renders.
  certify::Verdict verdict{};
  const std::string expected_out1 =
      independent_thesis_output(kSample + "path.txt", 0.5, "path.txt", &verdict);
  EXPECT_EQ(with_sorted_points(test::read_text_file(dir + "/OUT1")),
            with_sorted_points(expected_out1));
  EXPECT_NE(t.out.find(std::string("verdict: ") + certify::to_string(verdict) + "\n"),
            std::string::npos);

  // The typed WCS segment is saved as a path file and verifies to the stored OUT2.
  EXPECT_EQ(test::read_text_file(dir + "/OUT2.path.txt"), "1\n2\n0,20,6,0,0,-1,30\n4\n4\n0.3\n4\n");
  certify::Verdict typed_verdict{};
  EXPECT_EQ(with_sorted_points(test::read_text_file(dir + "/OUT2")),
            with_sorted_points(independent_thesis_output(dir + "/OUT2.path.txt", 0.5, "SCREEN",
                                                         &typed_verdict)));
  EXPECT_NE(t.out.find(std::string("verdict: ") + certify::to_string(typed_verdict) + "\n"),
            std::string::npos);

  // Animation documents (JSON reports until the HTML writer lands) for motions 1, 3 and 4;
  // motion 2 was not stored, so its document is numbered too.
  for (const std::string name : {"OUT1.json", "OUT2.json", "grpvss-motion-2.json",
                                 "grpvss-motion-4.json"}) {
    const nlohmann::json report = nlohmann::json::parse(test::read_text_file(dir + "/" + name));
    EXPECT_EQ(report.at("schema"), "grpvss-report/1") << name;
  }
  EXPECT_EQ(test::directory_entries(dir),
            (std::vector<std::string>{"OUT1", "OUT1.json", "OUT1.svg", "OUT2", "OUT2.json",
                                      "OUT2.path.txt", "OUT2.svg", "grpvss-motion-2.json",
                                      "grpvss-motion-2.svg", "grpvss-motion-4.json"}));
  // The picture is drawn in the view typed at the start (ANGLEX/Y/Z, SCALE, SHIFT).
  ASSERT_TRUE(out1.contains("scene"));
  report::SvgView typed_view;
  typed_view.angle_x_deg = -75.0;
  typed_view.angle_y_deg = 0.0;
  typed_view.angle_z_deg = 85.0;
  typed_view.scale = 1.5;
  typed_view.shift = {-20.0, -10.0, 0.0};
  EXPECT_EQ(test::read_text_file(dir + "/OUT1.svg"),
            report::render_step_svg(out1, first_collision, typed_view, "OUT1.json"));
  EXPECT_NE(test::read_text_file(dir + "/OUT1.svg"),
            report::render_step_svg(out1, first_collision, report::SvgView{}, "OUT1.json"));
}

// A short complete session: robot, trapezoids, environment, tolerance, default view, one
// typed PTP (JCS) segment, not stored, menu 5 (animation again), exit.
std::vector<std::string> short_session() {
  return {"1", "1", kSample + "environment.txt", "1", "", "",
          "2", "1", "10,20", "10,20", "1,1", "10,20", "", "", "n", "", "", "", "5", "", "", "1",
          "6"};
}

TEST(InteractiveSession, ShortSessionSeesTheAnimationAgainInSteppingMode) {
  const std::string dir = test::make_temporary_directory("interactive-short");
  const Transcript t = run_session(short_session(), dir);
  ASSERT_EQ(t.end, SessionEnd::kExitChosen) << t.out;
  EXPECT_EQ(t.motions, 1);
  EXPECT_TRUE(t.view.stepping);
  EXPECT_TRUE(appear_in_order(t.out, {"THE REPORT OF THIS PATH (WITH THE SCENE) IS IN " + dir + "/grpvss-motion-1.json\n",
                                      "THE REPORT OF THIS PATH (WITH THE SCENE) IS IN " + dir + "/grpvss-motion-1-2.json\n",
                                      "GRPVSS SESSION ENDED\n"}));
}

TEST(InteractiveSession, EndOfInputAtEveryPromptExitsCleanly) {
  const std::vector<std::string> answers = short_session();
  for (std::size_t given = 0; given < answers.size(); ++given) {
    const std::string dir = test::make_temporary_directory("interactive-eof");
    const Transcript t = run_session(
        std::vector<std::string>(answers.begin(), answers.begin() + static_cast<long>(given)), dir);
    EXPECT_EQ(t.end, SessionEnd::kEndOfInput) << "after " << given << " answers:\n" << t.out;
    EXPECT_EQ(exit_code(t.end), 0);
    const std::string goodbye = "END OF INPUT: GRPVSS SESSION ENDED\n";
    ASSERT_GE(t.out.size(), goodbye.size());
    EXPECT_EQ(t.out.substr(t.out.size() - goodbye.size()), goodbye) << given;
    EXPECT_EQ(count_of(t.out, "GRPVSS SESSION ENDED"), 1u);
  }
}

TEST(InteractiveSession, TooManyInvalidAnswersInARowEndWithExitCode2) {
  const std::string dir = test::make_temporary_directory("interactive-invalid");
  const Transcript t = run_session(std::vector<std::string>(30, "7"), dir, 20);
  EXPECT_EQ(t.end, SessionEnd::kTooManyInvalidAnswers);
  EXPECT_EQ(exit_code(t.end), 2);
  EXPECT_EQ(count_of(t.out, "INVALID ANSWER: enter one of the option numbers 1 to 2\n"), 20u);
  EXPECT_EQ(count_of(t.out, "WHICH ROBOT ARE YOU GOING TO SIMULATE ?"), 20u);
  EXPECT_NE(t.out.find("20 INVALID ANSWERS IN A ROW: GRPVSS SESSION ENDED\n"), std::string::npos);
}

TEST(InteractiveSession, AValidAnswerRestartsTheInvalidCount) {
  const std::string dir = test::make_temporary_directory("interactive-count");
  // 2 invalid, a valid robot choice, 2 invalid at the next question, then the end of input:
  // with a bound of 3 the session is not ended by invalid answers.
  const Transcript t = run_session({"x", "0", "1", "3", "", }, dir, 3);
  EXPECT_EQ(t.end, SessionEnd::kEndOfInput) << t.out;
  EXPECT_EQ(count_of(t.out, "INVALID ANSWER"), 4u);
}

TEST(InteractiveSession, BadFilesAreAskedAgainWithTheReadersMessage) {
  const std::string dir = test::make_temporary_directory("interactive-files");
  const Transcript t = run_session(
      {"2", dir + "/no-robot.txt", "2", kSample + "robot.txt", "2", dir + "/no-table.txt", "1",
       kSample + "path.txt", kSample + "environment.txt", "0", "-1", "abc", "0.25,"},
      dir);
  EXPECT_EQ(t.end, SessionEnd::kEndOfInput);
  EXPECT_TRUE(appear_in_order(
      t.out, {"TO-BE-SIMULATED ROBOT SHOULD BE IN A FILE\n", "INVALID ANSWER: " + dir + "/no-robot.txt:",
              "ROBOT FILE " + kSample + "robot.txt: 4 JOINTS",
              "ENTER THE FILE NAME OF THE MOTION-TIME TABLE\n", "INVALID ANSWER: " + dir + "/no-table.txt:",
              "1. IDEAL TRAPEZOID FUNCTIONS\n",
              "INVALID ANSWER: " + kSample + "path.txt:", "ENVIRONMENT FILE " + kSample + "environment.txt: 2 OBSTACLES\n",
              "INVALID ANSWER: enter one number > 0\n", "INVALID ANSWER: enter one number > 0\n",
              "INVALID ANSWER: 'abc' is not a number\n", "THE TOLERANCE VALUE = 0.25\n"}));
}

TEST(InteractiveAnswers, NumberListsFollowTheThesisCommaConvention) {
  std::string why;
  EXPECT_EQ(parse_number_list("50.,4.,", why), (std::vector<double>{50.0, 4.0}));
  EXPECT_EQ(parse_number_list(" -75., 0. ,85.", why), (std::vector<double>{-75.0, 0.0, 85.0}));
  EXPECT_EQ(parse_number_list("1 2\t3", why), (std::vector<double>{1.0, 2.0, 3.0}));
  EXPECT_EQ(parse_number_list("1e-3,", why), (std::vector<double>{1e-3}));
  EXPECT_FALSE(parse_number_list("1,,2", why));
  EXPECT_EQ(why, "an empty field between commas");
  EXPECT_FALSE(parse_number_list("nan", why));
  EXPECT_FALSE(parse_number_list("1e999", why));
  EXPECT_FALSE(parse_number_list("1.5x", why));
  EXPECT_EQ(why, "'1.5x' is not a number");
  EXPECT_FALSE(parse_number_list("", why));
  EXPECT_EQ(parse_yes_no("", false), false);
  EXPECT_EQ(parse_yes_no("", true), true);
  EXPECT_EQ(parse_yes_no(" yes\r", false), true);
  EXPECT_EQ(parse_yes_no("n", true), false);
  EXPECT_FALSE(parse_yes_no("maybe", true));
  EXPECT_EQ(parse_option("6", 6), 6);
  EXPECT_EQ(parse_option("1.", 2), 1);
  EXPECT_FALSE(parse_option("7", 6));
  EXPECT_FALSE(parse_option("0", 6));
  EXPECT_FALSE(parse_option("1x", 6));
}

struct CliRun {
  int exit_code = -1;
  std::string out;
};

CliRun run_cli_with_stdin(const std::string& dir, const std::string& input,
                          const std::string& options = "") {
  const std::string input_file = dir + "/answers.txt";
  {
    std::FILE* file = std::fopen(input_file.c_str(), "w");
    std::fwrite(input.data(), 1, input.size(), file);
    std::fclose(file);
  }
  const std::string command = "cd '" + dir + "' && GRPVSS_DATA_DIR='" + kDataDir + "' '" +
                              GRPVSS_CLI + "' interactive " + options + " < '" + input_file + "' 2>&1";
  CliRun result;
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) return result;
  char buffer[4096];
  std::size_t n;
  while ((n = fread(buffer, 1, sizeof buffer, pipe)) > 0) result.out.append(buffer, n);
  const int status = pclose(pipe);
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return result;
}

TEST(InteractiveCli, PipedStdinRunsTheSessionAndEchoesTheAnswers) {
  const std::string dir = test::make_temporary_directory("interactive-cli");
  const CliRun r = run_cli_with_stdin(dir, join_lines(short_session()));
  EXPECT_EQ(r.exit_code, 0) << r.out;
  // Piped answers are echoed after their prompt, as the thesis prints the entered data.
  EXPECT_TRUE(appear_in_order(r.out, {"ENTER ONE OF THE OPTION NUMBERS\n> 1\n",
                                      "ENTER THE TOLERANCE VALUE\n(SAME LENGTH UNITS AS THE "
                                      "ROBOT FILE, > 0)\n> 1\n",
                                      "THE REPORT OF THIS PATH (WITH THE SCENE) IS IN "
                                      "./grpvss-motion-1.json\n",
                                      "GRPVSS SESSION ENDED\n"}));
  EXPECT_TRUE(std::filesystem::exists(dir + "/grpvss-motion-1.json"));
  // The executable passes the viewer's HTML writer: a page, or (a build without the viewer
  // bundle) the reason there is none.
  const bool html = r.out.find("THE ANIMATION OF THIS PATH IS IN ./grpvss-motion-1.html "
                               "(OPEN IT IN A WEB BROWSER)\n") != std::string::npos;
  EXPECT_NE(html, r.out.find("NO HTML ANIMATION: ") != std::string::npos) << r.out;
  EXPECT_EQ(html, std::filesystem::exists(dir + "/grpvss-motion-1.html"));

  const CliRun empty = run_cli_with_stdin(dir, "");
  EXPECT_EQ(empty.exit_code, 0);
  EXPECT_NE(empty.out.find("END OF INPUT: GRPVSS SESSION ENDED\n"), std::string::npos);

  const CliRun invalid = run_cli_with_stdin(dir, join_lines(std::vector<std::string>(25, "9")));
  EXPECT_EQ(invalid.exit_code, 2);
}

}  // namespace
// `interactive --cell`: the cell's robot and obstacles replace the robot and environment
// questions, its tolerance (0.005 m, printed with its digits) is the default, and the summary
// names links and obstacles (data/sixaxis: the path through the post).
TEST(InteractiveCli, ACellReplacesTheRobotAndEnvironmentQuestions) {
  const std::string dir = test::make_temporary_directory("interactive-cell");
  const std::string six = std::string(GRPVSS_SOURCE_DIR) + "/data/sixaxis/";
  const CliRun r = run_cli_with_stdin(
      dir, join_lines({"1", "", "", "", "1", six + "path-collision.txt", "n", "", "", "", "6"}),
      "--cell " + six + "cell.yaml");
  EXPECT_EQ(r.exit_code, 0) << r.out;
  EXPECT_TRUE(appear_in_order(
      r.out, {"CELL FILE " + six + "cell.yaml: ROBOT grpvss_sixaxis, 6 JOINTS, IK OPW closed form\n",
              "CELL FILE " + six + "cell.yaml: 6 OBSTACLE HULLS (pedestal, table, fixture piece 0, "
                                   "fixture piece 1, fixture piece 2, post)\n",
              "ENTER THE TOLERANCE VALUE (DEFAULT = 0.005)\n", "THE TOLERANCE VALUE = 0.005\n",
              "END EFFECTOR POSITION ", "verdict: COLLISION\nmode: certified  tolerance: 0.005  steps: 8 ",
              "interference: link_4 hull 0 / post, ", "GRPVSS SESSION ENDED\n"}))
      << r.out;
  EXPECT_EQ(r.out.find("WHICH ROBOT ARE YOU GOING TO SIMULATE"), std::string::npos) << r.out;
  const CliRun bad = run_cli_with_stdin(dir, "", "--cell " + dir + "/missing.yaml");
  EXPECT_EQ(bad.exit_code, 2) << bad.out;
}

}  // namespace grpvss::app::interactive

// Interference episodes: the runs of consecutive steps at which one (link hull, obstacle) pair
// interferes, built from hand-made steps and from the verifier's own runs.
#include "certify/interference_episodes.hpp"

#include <set>
#include <string>
#include <tuple>

#include <gtest/gtest.h>

#include "grpvss/certify/verifier.hpp"
#include "grpvss/io/environment_file.hpp"
#include "grpvss/io/path_file.hpp"
#include "grpvss/io/robot_file.hpp"
#include "grpvss/motion/kinematics_adapter.hpp"
#include "support/data_paths.hpp"

namespace grpvss::certify {
namespace {

using grpvss::test::ibm7545_file;

StepRecord step_with(int index, int segment, double time, std::vector<PairContact> contacts) {
  StepRecord step;
  step.index = index;
  step.segment = segment;
  step.path_time = time;
  step.contacts = std::move(contacts);
  return step;
}

PairContact pair(int link, int hull, int obstacle, bool unexpanded) {
  return {link, hull, obstacle, unexpanded};
}

TEST(InterferenceEpisodeTracker, ARunEndsAtTheFirstStepWithoutThePairAndAReturnStartsANewOne) {
  InterferenceEpisodeTracker tracker;
  tracker.add(step_with(0, 0, 0.0, {}));
  tracker.add(step_with(1, 1, 1.0, {pair(2, 0, 1, false)}));
  tracker.add(step_with(2, 1, 1.5, {pair(2, 0, 1, true), pair(3, 1, 0, false)}));
  tracker.add(step_with(3, 2, 2.0, {pair(2, 0, 1, true)}));
  tracker.add(step_with(4, 2, 2.5, {pair(2, 0, 1, false)}));
  tracker.add(step_with(5, 2, 3.0, {}));
  tracker.add(step_with(6, 2, 3.5, {pair(3, 1, 0, false)}));
  const auto& episodes = tracker.episodes();
  ASSERT_EQ(episodes.size(), 3u);
  // Ordered by first step: (2,0,1) from 1, (3,1,0) at 2 only, (3,1,0) again at 6.
  EXPECT_EQ(std::tie(episodes[0].link, episodes[0].hull, episodes[0].obstacle),
            std::make_tuple(2, 0, 1));
  EXPECT_EQ(episodes[0].first_step, 1);
  EXPECT_EQ(episodes[0].last_step, 4);
  EXPECT_EQ(episodes[0].first_segment, 1);
  EXPECT_EQ(episodes[0].last_segment, 2);
  EXPECT_EQ(episodes[0].first_time, 1.0);
  EXPECT_EQ(episodes[0].last_time, 2.5);
  EXPECT_EQ(episodes[0].first_collision_step, 2);
  EXPECT_EQ(episodes[0].last_collision_step, 3);
  EXPECT_EQ(episodes[0].cleared_step, 5);  // the first step without the pair
  EXPECT_EQ(episodes[0].cleared_time, 3.0);
  EXPECT_EQ(std::tie(episodes[1].link, episodes[1].hull, episodes[1].obstacle),
            std::make_tuple(3, 1, 0));
  EXPECT_EQ(episodes[1].first_step, 2);
  EXPECT_EQ(episodes[1].last_step, 2);
  EXPECT_FALSE(episodes[1].first_collision_step.has_value());
  EXPECT_FALSE(episodes[1].last_collision_step.has_value());
  EXPECT_EQ(episodes[2].first_step, 6);
  EXPECT_EQ(episodes[2].last_step, 6);
  EXPECT_EQ(episodes[1].cleared_step, 3);
  EXPECT_FALSE(episodes[2].cleared_step.has_value());  // the path ends with the pair in it
  EXPECT_FALSE(episodes[2].cleared_time.has_value());
}

TEST(InterferenceEpisodeTracker, AStartInContactOpensAnEpisodeAtStepZero) {
  InterferenceEpisodeTracker tracker;
  tracker.add(step_with(0, 0, 0.0, {pair(1, 0, 0, true)}));
  tracker.add(step_with(1, 1, 0.4, {pair(1, 0, 0, false)}));
  ASSERT_EQ(tracker.episodes().size(), 1u);
  EXPECT_EQ(tracker.episodes()[0].first_step, 0);
  EXPECT_EQ(tracker.episodes()[0].first_segment, 0);
  EXPECT_EQ(tracker.episodes()[0].last_step, 1);
  EXPECT_EQ(tracker.episodes()[0].first_collision_step, 0);
  EXPECT_EQ(tracker.episodes()[0].last_collision_step, 0);
}

// Every step's contacts agree with its flags and its points, and every episode is exactly a
// maximal run of steps carrying its pair.
void expect_consistent(const VerificationResult& result) {
  std::vector<const StepRecord*> steps{&*result.start};
  for (const StepRecord& step : result.steps) steps.push_back(&step);
  std::set<std::tuple<int, int, int, int>> in_episodes;  // (step, link, hull, obstacle)
  for (const InterferenceEpisode& episode : result.interference_episodes) {
    for (int k = episode.first_step; k <= episode.last_step; ++k) {
      in_episodes.insert({k, episode.link, episode.hull, episode.obstacle});
    }
  }
  std::size_t contact_count = 0;
  for (const StepRecord* step : steps) {
    EXPECT_EQ(!step->contacts.empty(), step->expanded_interferes) << "step " << step->index;
    bool any_unexpanded = false;
    for (const PairContact& contact : step->contacts) {
      any_unexpanded |= contact.unexpanded_collides;
      EXPECT_TRUE(in_episodes.count({step->index, contact.link, contact.hull, contact.obstacle}))
          << "step " << step->index;
      ++contact_count;
    }
    EXPECT_EQ(any_unexpanded, step->unexpanded_collides) << "step " << step->index;
    for (const InterferencePoint& point : step->interference_points) {
      bool listed = false;
      for (const PairContact& contact : step->contacts) {
        listed |= contact.link == point.link && contact.hull == point.hull &&
                  contact.obstacle == point.obstacle;
      }
      EXPECT_TRUE(listed) << "step " << step->index;
    }
  }
  EXPECT_EQ(in_episodes.size(), contact_count);  // no episode covers a step without its pair
}

class Ibm7545Episodes : public ::testing::Test {
 protected:
  VerificationRun run(const std::string& environment_file, const PathProgram& program,
                      ClearClaim claim = ClearClaim::kMotion) {
    robot_ = io::read_robot_file(ibm7545_file("robot.txt"));
    environment_ = io::read_environment_file(ibm7545_file(environment_file));
    program_ = program;
    kinematics_ =
        motion::make_kinematics_access(robot_, motion::select_ik({}, robot_, "robot.txt"));
    SetupRequest options;
    options.tolerance = 0.5;
    options.claim = claim;
    return verify(robot_, environment_, program_, kinematics_, resolve_setup(options));
  }
  RobotModel robot_;
  Environment environment_;
  PathProgram program_;
  motion::KinematicsAccess kinematics_;
};

// The Table 3 PTP operation crosses the post (obstacle 0) with the quill (link 4 hull 0).
TEST_F(Ibm7545Episodes, TheTable3PtpOperationHasOneEpisodeOfTheQuillInThePost) {
  const RobotModel robot = io::read_robot_file(ibm7545_file("robot.txt"));
  const VerificationRun ptp =
      run("bench-environment.txt",
          io::parse_path_file("1\n1\n50.,3.\n50.,3.\n4.,0.3\n50.,3.\n", "ptp.txt", robot),
          ClearClaim::kSteps);  // the step rule at the steps: the claim motion steps finer
  ASSERT_EQ(ptp.result.verdict, Verdict::kCollision);
  expect_consistent(ptp.result);
  ASSERT_EQ(ptp.result.interference_episodes.size(), 1u);
  const InterferenceEpisode& quill = ptp.result.interference_episodes[0];
  EXPECT_EQ(std::tie(quill.link, quill.hull, quill.obstacle), std::make_tuple(4, 0, 0));
  ASSERT_TRUE(quill.first_collision_step.has_value());
  EXPECT_EQ(quill.first_collision_step, ptp.result.collision_step);
  // The expanded quill meets the post one step before the nominal one does. The pair is not
  // sampled while it collides: the step after the collision has the quill out of the post,
  // which the episode records as the time it is clear by.
  EXPECT_EQ(quill.first_step, *quill.first_collision_step - 1);
  EXPECT_EQ(quill.last_step, *quill.last_collision_step);
  EXPECT_EQ(quill.first_time, ptp.result.steps.at(quill.first_step - 1).path_time);
  ASSERT_TRUE(quill.cleared_step.has_value());
  EXPECT_EQ(*quill.cleared_step, quill.last_step + 1);
  EXPECT_EQ(quill.cleared_time, ptp.result.steps.at(*quill.cleared_step - 1).path_time);
}

// The thesis's sample path: link 3's two hulls hit obstacle 0 in segment 1, the quill only
// comes within the tolerance; in both modes the episodes match the steps.
TEST_F(Ibm7545Episodes, TheSamplePathsEpisodesMatchItsStepsInBothModes) {
  const RobotModel robot = io::read_robot_file(ibm7545_file("robot.txt"));
  const PathProgram program = io::read_path_file(ibm7545_file("path.txt"), robot);
  const VerificationRun certified = run("environment.txt", program);
  expect_consistent(certified.result);
  std::set<std::tuple<int, int, int>> colliding;
  for (const InterferenceEpisode& episode : certified.result.interference_episodes) {
    if (episode.first_collision_step) colliding.insert({episode.link, episode.hull, episode.obstacle});
  }
  EXPECT_EQ(colliding, (std::set<std::tuple<int, int, int>>{{3, 0, 0}, {3, 1, 0}}));

  SetupRequest thesis;
  thesis.tolerance = 0.5;
  thesis.mode = ResolutionMode::kThesis;
  const VerificationRun by_thesis_rule =
      verify(robot_, environment_, program_, kinematics_, resolve_setup(thesis));
  expect_consistent(by_thesis_rule.result);
}

}  // namespace
}  // namespace grpvss::certify

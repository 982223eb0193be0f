#pragma once
/// \file
/// \brief The thesis's output file (Appendix A.3), rendered from a verification run.
///
/// Layout (docs/thesis-output.md): the tolerance line; in certified mode only, one added line
/// `THE RESOLUTION MODE = CERTIFIED` (thesis mode reproduces A.3 with nothing added); per
/// segment its header `THE kTH SEGMENT OF THE PATH INPUT FROM FILE <label>` and the
/// specification block of its kind; per step the joint values (degrees for revolute joints)
/// and the interference points (x, y, z, tab-separated); each error as the three-line thesis
/// block; then `TOTAL n STEPS IN THIS PATH` and `COLLISIONS DETECTED IN THIS PATH` or
/// `NO COLLISION DETECTED IN THIS PATH`. Numbers have 2 decimals, ordinals are `1TH`, `2TH`,
/// `3TH` as in the thesis.

#include <string>
#include <vector>

#include "grpvss/evidence/verification_observer.hpp"
#include "grpvss/evidence/verification_result.hpp"
#include "grpvss/model/environment.hpp"
#include "grpvss/model/robot_model.hpp"
#include "grpvss/report/spill_file.hpp"

namespace grpvss::report {

/// \brief The labels an interference-point line names its pair with (docs/thesis-output.md#names):
/// empty for thesis files (A.3 has no room for them), else one label per link (link_label())
/// and per obstacle hull (obstacle_label()).
struct ThesisNames {
  std::vector<std::string> links;
  std::vector<std::string> obstacles;
  bool empty() const { return links.empty() && obstacles.empty(); }
  /// Empty when neither `robot`'s links nor `environment`'s obstacles have names.
  static ThesisNames of(const RobotModel& robot, const Environment& environment);
};

/// \brief Renders `result` in the A.3 layout; `joint_types[i]` is the type of joint i+1
/// (revolute values and speeds are printed in degrees).
/// \throws std::logic_error if the result is inconsistent (a joint vector of the wrong size,
///         a step whose segment has no record, steps out of order).
std::string render_thesis_output(const certify::VerificationResult& result,
                                 const std::vector<JointType>& joint_types,
                                 const ThesisNames& names = {});

/// Same, with the joint types taken from `robot`.
std::string render_thesis_output(const certify::VerificationResult& result,
                                 const RobotModel& robot);

/// One step's block: `IN nTH STEP, THE JOINT VALUES ARE`, the values, the interference count
/// and the points, with their blank lines; with `names`, each point line ends with a tab and
/// its pair (`link_4 hull 0 / post`).
std::string thesis_step_block(const certify::StepRecord& step,
                              const std::vector<JointType>& joint_types,
                              const ThesisNames& names = {});

/// \brief The thesis output file written while the verification runs, memory independent of
/// the number of steps (docs/reliability.md#resource-bounds): each step's block goes to a
/// scratch file as it arrives (SpillFile), finish() writes the file around them. The bytes are
/// those of render_thesis_output() for the same run. Nothing appears under `path` before
/// finish() succeeds (AtomicOutputFile).
class ThesisOutputStream : public certify::VerificationObserver {
 public:
  /// \throws InputError when no scratch file can be created next to `path`.
  ThesisOutputStream(std::string path, bool force, std::vector<JointType> joint_types,
                     ThesisNames names = {});
  ~ThesisOutputStream() override;

  /// \throws std::logic_error if the indices do not increase or a segment's steps are split.
  void on_step(const certify::StepRecord& step) override;

  /// Writes and publishes the file; `result` is the finished run (its `steps` are not read).
  /// \throws OutputExistsError, InputError as write_file_atomically(); std::logic_error when a
  ///         step's segment has no record.
  void finish(const certify::VerificationResult& result);

 private:
  struct SegmentRange {
    int segment;
    std::uint64_t begin;  ///< byte range of the segment's step blocks in `steps_`
    std::uint64_t end;
  };
  std::string path_;
  bool force_;
  std::vector<JointType> joint_types_;
  ThesisNames names_;
  SpillFile steps_;
  std::vector<SegmentRange> ranges_;  ///< one per segment with steps, in path order
  int last_index_ = 0;
  bool collisions_ = false;
};

/// True when a step makes the thesis print `COLLISIONS DETECTED IN THIS PATH`.
bool step_reports_collision(const certify::StepRecord& step);

/// True when the thesis would print `COLLISIONS DETECTED IN THIS PATH`: some step has
/// interference points, an interfering expanded robot, or a colliding unexpanded robot.
bool thesis_reports_collision(const certify::VerificationResult& result);

/// The n of `TOTAL n STEPS IN THIS PATH`: the index of the last step (steps are numbered
/// 1, 2, ... over the whole path), 0 without steps.
/// \throws std::logic_error if the step indices do not increase.
int total_steps(const certify::VerificationResult& result);

}  // namespace grpvss::report

#pragma once
/// \file
/// \brief The JSON report (with its `scene`) written while the verification runs, in memory
/// independent of the number of steps (docs/reliability.md#resource-bounds).
///
/// The report's two long arrays, `steps` and `scene.steps`, are rendered element by element as
/// the steps arrive, into scratch files (SpillFile). finish() builds the rest of the report as
/// a small document whose long arrays (those two and `segments`) are placeholders, dumps it as
/// render_json_report() does and writes it around the scratch files and the segments, dumped
/// one at a time (streamed_json.hpp). The bytes are those of
/// render_json_report() of report_to_json() with `scene` = scene_to_json() for the same run.
/// Optionally the same report is also kept in the viewer page's form (compact, every `<`
/// written `\u003c`), for write_script_safe_report().

#include <memory>
#include <string>
#include <vector>

#include "grpvss/evidence/verification_observer.hpp"
#include "grpvss/model/robot_model.hpp"
#include "grpvss/report/input_digests.hpp"
#include "grpvss/report/scene_json.hpp"

namespace grpvss::report {

class AtomicOutputFile;

class JsonReportStream : public certify::VerificationObserver {
 public:
  struct Outputs {
    std::string json_path;      ///< the report file; empty: none
    bool script_safe = false;   ///< also keep the viewer page's form (write_script_safe_report)
    std::string scratch_path;   ///< scratch files go to this path's directory
    bool force = false;
  };

  /// `robot` must outlive the stream. \throws InputError when no scratch file can be created
  /// next to `outputs.scratch_path`.
  JsonReportStream(const RobotModel& robot, Outputs outputs);
  ~JsonReportStream() override;

  /// \throws std::logic_error on a NaN, a wrong-sized joint vector, or decreasing indices.
  void on_step(const certify::StepRecord& step) override;

  /// Completes the report of the finished run `result` (its `steps` are not read) with its
  /// scene (drawn from `cell`, the cell the run used, as scene_to_json() does); writes and
  /// publishes the report file when there is one.
  /// \throws OutputExistsError, InputError as write_file_atomically().
  void finish(const certify::VerificationResult& result, const certify::RobotCell& cell,
              const InputDigests& digests, const std::string& generated_at);

  /// After finish() (whose `result` must still exist), with Outputs::script_safe: appends the
  /// report to `output` as the viewer page embeds it (compact dump, invalid UTF-8 replaced,
  /// `<` as `\u003c`).
  void write_script_safe_report(AtomicOutputFile& output);

 private:
  struct Form;

  const RobotModel& robot_;
  Outputs outputs_;
  std::vector<JointType> joint_types_;
  SceneStepPoses poses_;
  std::unique_ptr<Form> pretty_;       ///< the report file's form (when json_path is set)
  std::unique_ptr<Form> script_safe_;  ///< the viewer page's form (when script_safe)
  const std::vector<certify::SegmentRecord>* segments_ = nullptr;  ///< finish()'s result's
  int last_index_ = 0;
  bool collisions_ = false;
};

}  // namespace grpvss::report

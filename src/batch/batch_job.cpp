#include "batch_job.hpp"

#include <exception>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "grpvss/batch/joint_trajectory_input.hpp"
#include "grpvss/batch/motion_statement.hpp"
#include "grpvss/batch/robot_program_input.hpp"
#include "grpvss/certify/verifier.hpp"
#include "grpvss/common/input_error.hpp"
#include "grpvss/io/path_file.hpp"
#include "grpvss/io/text_file.hpp"
#include "grpvss/motion/kinematics_adapter.hpp"
#include "grpvss/motion/trajectory.hpp"
#include "grpvss/report/certificate_output.hpp"
#include "grpvss/io/length_unit.hpp"
#include "grpvss/report/file_units.hpp"
#include "grpvss/report/input_digests.hpp"
#include "grpvss/report/json_report.hpp"
#include "grpvss/report/json_report_stream.hpp"
#include "grpvss/report/thesis_output.hpp"
#include "grpvss/common/file_label.hpp"

namespace grpvss::batch {
namespace {

constexpr int kExitInputError = 2;
constexpr int kExitInternalError = 70;

/// Counts the accepted steps (the run keeps none in memory).
class StepCounter : public certify::VerificationObserver {
 public:
  void on_step(const certify::StepRecord&) override { ++steps; }
  int steps = 0;
};

/// The report writers one job asked for, each an observer of the run.
struct JobReports {
  std::optional<report::ThesisOutputStream> thesis_output;
  std::optional<report::JsonReportStream> json_report;
  std::optional<report::CertificateStream> certificate;
  StepCounter counter;
};

void attach_reports(const BatchJob& job, const RobotModel& robot, const Environment& environment,
                    bool force, JobReports& reports, certify::RunHooks& hooks) {
  const JobOutputs& out = job.outputs;
  hooks.observers.push_back(&reports.counter);
  if (!out.thesis_output.empty()) {
    reports.thesis_output.emplace(out.thesis_output, force, report::joint_types_of(robot),
                                  report::ThesisNames::of(robot, environment));
    hooks.observers.push_back(&*reports.thesis_output);
  }
  if (!out.json.empty() || !out.html.empty()) {
    report::JsonReportStream::Outputs outputs;
    outputs.json_path = out.json;
    outputs.script_safe = !out.html.empty();
    outputs.scratch_path = out.json.empty() ? out.html : out.json;
    outputs.force = force;
    reports.json_report.emplace(robot, std::move(outputs));
    hooks.observers.push_back(&*reports.json_report);
  }
  if (!out.certificate.empty()) {
    reports.certificate.emplace(out.certificate, force);
    hooks.observers.push_back(&*reports.certificate);
  }
}

/// The smallest clearance, named when the model has names (a cell's).
std::optional<SmallestClearance> smallest_clearance(const certify::VerificationResult& result,
                                                    const RobotModel& robot,
                                                    const Environment& environment) {
  std::optional<SmallestClearance> smallest;
  for (const certify::LinkClearanceSummary& link : result.link_clearances) {
    if (!smallest || link.min_clearance < smallest->clearance) {
      smallest = SmallestClearance{link.min_clearance, link.link, link.obstacle, link.step, {}, {}};
    }
  }
  if (!smallest) return smallest;
  const auto link = static_cast<std::size_t>(smallest->link);
  if (link < robot.links.size()) smallest->link_name = robot.links[link].name;
  if (smallest->obstacle >= 0 && environment.has_names()) {
    smallest->obstacle_name = obstacle_label(environment, smallest->obstacle);
  }
  return smallest;
}

/// Everything the job reads: the shared robot, environment and cell, the IK, its own motion (a
/// path program, a joint trajectory: `joint_motion` set, or a robot program: `robot_program`
/// set, its `path` in `program`).
struct JobInputs {
  std::shared_ptr<const LoadedRobot> robot;
  std::shared_ptr<const LoadedEnvironment> environment;
  std::shared_ptr<const kinematics::InverseKinematics> ik;
  PathProgram program;
  std::shared_ptr<const motion::JointTrajectoryMotion> joint_motion;
  std::optional<LoadedRobotProgram> robot_program;
  report::InputDigests digests;
  certify::VerificationSetup setup;
  std::vector<io::InputWarning> warnings;
};

/// The job's robot and environment (a cell file's, or thesis files'), and what the model
/// supplies to the options left unset.
cell::ModelInputs load_model(const VerifyOptions& options, SharedInputs& shared, JobInputs& inputs) {
  if (!options.cell_file.empty()) {
    const std::shared_ptr<const LoadedCellModel> model = shared.cell_model(model_sources(options));
    inputs.robot = model->robot;
    inputs.environment = model->environment;
    inputs.warnings = model->inputs.warnings;
    return model->inputs;
  }
  inputs.robot = shared.robot(options.robot_file);
  inputs.environment = shared.environment(options.environment_file);
  cell::ModelInputs thesis_model;
  thesis_model.robot_digest_file = options.robot_file;
  thesis_model.environment_digest_file = options.environment_file;
  return thesis_model;
}

/// The job's motion and its file's digest: the path program, or the joint trajectory or the
/// robot program read by the loader `grpvss verify --trajectory|--program` uses.
report::InputFileDigest load_motion(const VerifyOptions& options, const cell::ModelInputs& model,
                               JobInputs& inputs) {
  if (!options.program_file.empty()) {
    const std::optional<Eigen::VectorXd> start =
        resolve_start(options, inputs.robot->model, model.from_cell, "start");
    inputs.robot_program = load_robot_program(options.program_file, inputs.robot->model,
                                              ProgramPlacement{model.X_WR, model.X_FE},
                                              *inputs.ik, start);
    inputs.program = inputs.robot_program->path.path;
    for (const ProgramWarning& w : inputs.robot_program->warnings) {
      inputs.warnings.push_back({w.file, w.line, w.text});
    }
    return {options.program_file, report::sha256_hex_of_file(options.program_file)};
  }
  if (!options.trajectory_file.empty()) {
    inputs.joint_motion = load_joint_trajectory(options.trajectory_file, inputs.robot->model);
    return {options.trajectory_file, report::sha256_hex_of_file(options.trajectory_file)};
  }
  const std::string path_text = io::read_text_file(options.path_file);
  inputs.program = cell::parse_model_path(path_text, options.path_file, inputs.robot->model,
                                          model.model_units_per_cell_unit, cell::path_placement(model));
  return {options.path_file, report::sha256_hex(path_text)};
}

JobInputs load_inputs(const BatchJob& job, SharedInputs& shared) {
  const VerifyOptions& options = job.options;
  JobInputs inputs;
  const cell::ModelInputs model = load_model(options, shared, inputs);
  const std::string& robot_label_file =
      options.cell_file.empty() ? options.robot_file : options.cell_file;
  inputs.ik = motion::select_ik(parse_ik_choice(options.ik), inputs.robot->model, robot_label_file);
  const report::InputFileDigest motion_digest = load_motion(options, model, inputs);
  inputs.digests = {{model.robot_digest_file, inputs.robot->sha256},
                    {model.environment_digest_file, inputs.environment->sha256},
                    motion_digest,
                    model.model_unit ? std::string(io::length_unit_name(*model.model_unit)) : ""};
  VerifyOptions without_table = resolve_model_defaults(options, model);
  without_table.profile_table.clear();  // read once per batch, below
  certify::SetupRequest request = make_setup_request(without_table);
  if (!options.profile_table.empty()) {
    request.motion.table = shared.profile_table(options.profile_table);
  }
  request.motion.start = resolve_start(options, inputs.robot->model, model.from_cell, "start");
  request.path_label = file_label(motion_digest.file);
  inputs.setup = certify::resolve_setup(request);
  return inputs;
}

/// Finishes and publishes each report the job asked for, recording it in `result.outputs`.
void publish_reports(const BatchJob& job, const certify::VerificationRun& run,
                     const JobInputs& inputs, const SharedCell& cell, const std::string& ik_name,
                     const BatchOptions& options, JobReports& reports, JobResult& result) {
  const JobOutputs& out = job.outputs;
  if (reports.thesis_output) {
    reports.thesis_output->finish(run.result);
    result.outputs.push_back({"output", out.thesis_output});
  }
  if (reports.json_report) {
    reports.json_report->finish(run.result, cell.cell, inputs.digests, report::utc_timestamp_now());
    if (!out.json.empty()) result.outputs.push_back({"json", out.json});
  }
  if (!out.html.empty()) {
    options.html_writer(out.html, options.force, inputs.robot->model.name,
                        [&](report::AtomicOutputFile& file) {
                          reports.json_report->write_script_safe_report(file);
                        });
    result.outputs.push_back({"html", out.html});
  }
  if (reports.certificate) {
    const report::InputDigests& d = inputs.digests;
    nlohmann::json recorded = {{"robot", d.robot.sha256},
                               {"environment", d.environment.sha256},
                               {"ik", ik_name}};
    if (inputs.robot_program) {
      for (const auto& [name, value] : program_certificate_inputs(*inputs.robot_program)) {
        recorded[name] = value;
      }
    } else {
      recorded[inputs.joint_motion ? "trajectory" : "path"] = d.path.sha256;
    }
    reports.certificate->finish(run.certificate, recorded);
    result.outputs.push_back({"certificate", out.certificate});
  }
}

// `grpvss verify` (app/command_verify.cpp) on the shared cell, with the same report writers.
void verify_job(const BatchJob& job, SharedInputs& shared, const BatchOptions& options,
                JobResult& result) {
  const JobInputs inputs = load_inputs(job, shared);
  const RobotModel& robot = inputs.robot->model;
  result.warnings = inputs.warnings;
  const std::shared_ptr<const kinematics::InverseKinematics>& ik = inputs.ik;
  const std::shared_ptr<const SharedCell> cell =
      shared.cell(inputs.robot, inputs.environment, inputs.setup.cell);
  JobReports reports;
  certify::RunHooks hooks;
  hooks.keep_steps = false;
  attach_reports(job, robot, inputs.environment->model, options.force, reports, hooks);
  const motion::KinematicsAccess kinematics = motion::make_kinematics_access(robot, ik);
  certify::RunSettings settings = inputs.setup.run;
  if (!inputs.joint_motion) {  // a trajectory states its own (certify::verify)
    settings.motion_model = describe_path_motion(settings, settings.path_label, ik->name());
  }
  certify::VerificationRun run =
      inputs.joint_motion
          ? certify::verify(cell->cell, motion::Trajectory::from_joint_motion(robot, inputs.joint_motion),
                            kinematics, settings, hooks)
          : certify::verify(cell->cell, inputs.program, kinematics, settings, hooks);
  if (inputs.robot_program) run.result.motion_model = inputs.robot_program->description;
  publish_reports(job, run, inputs, *cell, ik->name(), options, reports, result);
  result.verdict = run.result.verdict;
  result.exit_code = verdict_exit_code(run.result.verdict);
  result.steps = reports.counter.steps;
  result.smallest_clearance =
      smallest_clearance(run.result, robot, inputs.environment->model);
}

}  // namespace

int verdict_exit_code(certify::Verdict verdict) {
  switch (verdict) {
    case certify::Verdict::kClear: return 0;
    case certify::Verdict::kCollision: return 1;
    case certify::Verdict::kWithinTolerance: return 3;
    case certify::Verdict::kError: return 4;
    case certify::Verdict::kUndecided: return 5;
  }
  throw std::logic_error("verdict_exit_code: unknown verdict");
}

JobResult run_job(const BatchJob& job, SharedInputs& shared, const BatchOptions& options) {
  JobResult result;
  result.index = job.index;
  result.line = job.line;
  result.id = job.id;
  try {
    verify_job(job, shared, options, result);
  } catch (const InputError& error) {
    result = JobResult{job.index, job.line, job.id, {}, kExitInputError, 0, {}, result.outputs,
                       JobError{error.file(), error.line(), error.what()}, result.warnings};
  } catch (const std::exception& error) {
    result = JobResult{job.index, job.line, job.id, {}, kExitInternalError, 0, {}, result.outputs,
                       JobError{"", 0, error.what()}, result.warnings};
  }
  return result;
}

}  // namespace grpvss::batch

#include "support/thesis_sample_result.hpp"

#include <cmath>
#include <vector>

#include "support/angles.hpp"

namespace grpvss::test {

namespace {

// As the readers convert (io/units.hpp): degrees * (pi/180).
double radians(double degrees) { return degrees * (kPi / 180.0); }

Eigen::VectorXd joints(std::initializer_list<double> file_values) {
  Eigen::VectorXd q(static_cast<Eigen::Index>(file_values.size()));
  int i = 0;
  for (double value : file_values) {
    q[i] = ibm7545_library_value(i, value);
    ++i;
  }
  return q;
}

WorldTarget world_target(double x, double y, double z, double kx, double ky, double kz,
                         double angle_degrees) {
  WorldTarget target;
  target.position_W = Eigen::Vector3d(x, y, z);
  target.axis_W = Eigen::Vector3d(kx, ky, kz);
  target.angle = radians(angle_degrees);
  return target;
}

struct PrintedStep {
  int index;
  int segment;
  std::vector<double> q;  // as printed: degrees, inches for joint 3
  std::vector<std::vector<double>> points;
};

// Transcribed from Appendix A.3 (tests/report/golden/thesis_a3_output_sample.txt).
const std::vector<PrintedStep>& printed_steps() {
  static const std::vector<PrintedStep> steps = {
      {1, 1, {1.05, 1.05, 0.24, 1.05}, {}},
      {2, 1, {5.26, 5.26, 0.69, 5.26}, {}},
      {3, 1, {8.25, 8.25, 0.99, 8.25}, {}},
      {4, 1, {11.20, 11.20, 1.28, 11.20}, {}},
      {33, 1, {61.16, 79.90, 2.45, 163.95}, {}},
      {34, 1, {61.16, 79.90, 2.45, 171.06}, {}},
      {35, 2, {62.69, 95.39, 3.00, -169.16}, {}},
      {36, 2, {67.36, 107.88, 3.56, -149.23}, {}},
      {40, 2, {112.45, 126.75, 5.77, -74.22}, {}},
      {41, 2, {125.16, 122.05, 6.32, -63.45},
       {{-11.40, 4.00, 9.00}, {-11.40, 4.00, 3.13}, {-14.46, 4.00, 3.13}, {-14.46, 4.00, 9.00},
        {-11.33, 3.76, 9.00}, {-14.10, 2.85, 9.00}, {-13.01, 2.31, 9.00}, {-11.86, 2.68, 9.00}}},
      {42, 2, {136.72, 114.01, 6.87, -57.16},
       {{-13.17, 0.00, 9.00}, {-15.60, 4.00, 8.63}, {-16.01, 4.00, 8.63}, {-15.60, 4.00, 9.00},
        {-16.01, 4.00, 9.00}, {-16.28, 0.00, 9.00}, {-13.17, 0.00, 8.63}, {-16.28, 0.00, 8.63},
        {-12.85, 0.92, 9.00}, {-12.19, 2.81, 9.00}, {-14.08, 3.47, 9.00}, {-16.62, 2.24, 9.00},
        {-17.28, 0.35, 9.00}, {-13.18, 1.39, 9.00}, {-13.48, 2.56, 9.00}, {-14.54, 3.14, 9.00},
        {-15.71, 2.83, 9.00}, {-16.30, 1.77, 9.00}, {-15.99, 0.60, 9.00}, {-14.93, 0.02, 9.00},
        {-13.76, 0.33, 9.00}}},
      {43, 2, {147.39, 103.13, 7.42, -54.62},
       {{-14.20, 0.00, 9.00}, {-18.44, 0.00, 9.00}, {-14.20, 0.00, 8.08}, {-18.44, 0.00, 8.08},
        {-14.03, 0.50, 9.00}, {-15.91, 1.16, 9.00}, {-17.80, 1.83, 9.00}, {-15.24, 0.00, 9.00},
        {-17.85, 0.00, 9.00}, {-15.24, 0.00, 2.03}, {-17.85, 0.00, 2.03}, {-15.28, 0.19, 9.00},
        {-16.31, 0.83, 9.00}, {-17.49, 0.58, 9.00}}},
      {44, 2, {157.66, 89.49, 7.98, -55.22}, {}},
      {45, 2, {166.68, 75.16, 8.45, -58.16},
       {{-18.53, -5.00, 1.00}, {-18.53, -5.00, 2.00}, {-21.47, -5.00, 1.00},
        {-21.47, -5.00, 2.00}, {-20.00, -5.00, 1.00}, {-18.48, -5.41, 2.00},
        {-21.38, -5.79, 2.00}, {-20.41, -6.52, 2.00}, {-19.21, -6.38, 2.00}}},
      {46, 3, {165.16, 73.64, 8.14, -56.64},
       {{-18.99, -5.00, 1.31}, {-21.78, -5.00, 1.31}, {-21.78, -5.00, 2.00},
        {-18.99, -5.00, 2.00}, {-20.00, -5.00, 1.31}, {-21.78, -5.02, 2.00},
        {-20.88, -5.82, 2.00}, {-19.67, -5.77, 2.00}}},
      {47, 3, {160.84, 69.32, 7.71, -52.32},
       {{-20.88, 0.00, 9.00}, {-21.86, 0.00, 9.00}, {-20.88, 0.00, 7.79}, {-21.86, 0.00, 7.79},
        {-21.46, 0.48, 9.00}}},
      {82, 3, {52.34, 50.00, 5.00, 50.00}, {}},
      {83, 3, {50.00, 50.00, 5.00, 50.00}, {}},
  };
  return steps;
}

}  // namespace

std::vector<JointType> ibm7545_joint_types() {
  return {JointType::kRevolute, JointType::kRevolute, JointType::kPrismatic,
          JointType::kRevolute};
}

RobotModel ibm7545_joint_type_model() {
  RobotModel robot;
  robot.name = "IBM 7545";
  for (JointType type : ibm7545_joint_types()) {
    Joint joint;
    joint.type = type;
    robot.joints.push_back(joint);
  }
  robot.links.resize(robot.joints.size() + 1);
  return robot;
}

double ibm7545_library_value(int joint, double file_value) {
  return ibm7545_joint_types()[static_cast<std::size_t>(joint)] == JointType::kRevolute
             ? radians(file_value)
             : file_value;
}

certify::VerificationResult thesis_a3_sample_result() {
  certify::VerificationResult result;
  result.tolerance = 1.0;
  result.mode = certify::ResolutionMode::kThesis;
  result.verdict = certify::Verdict::kError;
  result.path_file_label = "PATH";

  certify::SegmentRecord s1;
  s1.number = 1;
  s1.input.spec = PtpWorldSegment{world_target(0, 20, 8, 0, 0, -1, 30), joints({3, 3, 0.3, 3})};
  s1.input.source_line = 2;
  s1.start_q = joints({0, 0, 0, 0});
  s1.end_q = joints({61.16, 79.90, 2.45, 171.06});
  s1.first_step = 1;
  s1.last_step = 34;
  s1.simulated = true;

  certify::SegmentRecord s2;
  s2.number = 2;
  s2.input.spec = CpLineSegment{world_target(-20, -5, 2, 0, 0, -1, 30)};
  s2.input.source_line = 8;
  s2.start_q = s1.end_q;
  s2.end_q = joints({166.68, 75.16, 8.45, -58.16});
  s2.first_step = 35;
  s2.last_step = 45;
  s2.simulated = true;

  certify::SegmentRecord s3;
  s3.number = 3;
  s3.input.spec = PtpJointSegment{joints({50, 50, 5, 50}), joints({3, 3, 0.3, 3})};
  s3.input.source_line = 10;
  s3.start_q = s2.end_q;
  s3.end_q = joints({50, 50, 5, 50});
  s3.first_step = 46;
  s3.last_step = 83;
  s3.simulated = true;

  certify::SegmentRecord s4;
  s4.number = 4;
  s4.input.spec = CpLineSegment{world_target(15, 2, 8, 0, 0, -1, 30)};
  s4.input.source_line = 15;
  s4.start_q = s3.end_q;
  s4.simulated = false;

  result.segments = {s1, s2, s3, s4};

  for (const PrintedStep& printed : printed_steps()) {
    certify::StepRecord step;
    step.index = printed.index;
    step.segment = printed.segment;
    step.q.resize(static_cast<Eigen::Index>(printed.q.size()));
    for (std::size_t j = 0; j < printed.q.size(); ++j) {
      step.q[static_cast<Eigen::Index>(j)] = ibm7545_library_value(static_cast<int>(j), printed.q[j]);
    }
    for (const auto& p : printed.points) {
      certify::InterferencePoint point;
      point.p_W = Eigen::Vector3d(p[0], p[1], p[2]);
      step.interference_points.push_back(point);
    }
    step.expanded_interferes = !step.interference_points.empty();
    result.steps.push_back(step);
  }

  certify::PathError error;
  error.code = 3;
  error.segment = 4;
  error.step = 83;
  error.message = "final position of segment 4 is out of the workspace";
  result.errors.push_back(error);
  return result;
}

}  // namespace grpvss::test

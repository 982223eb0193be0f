#pragma once
// The real-robot benchmark cells and programs (docs/performance.md#real-robots-and-fcl):
// the UR5e and the Panda of ../shared/robots and the six-axis robot of data/sixaxis, each
// among 10, 100 or 1,000 generated obstacles (boxes, cylinders, a three-part mesh, some thin),
// built through the project's own cell loader from generated YAML; PTP programs whose
// segments the certified verifier proves CLEAR (the timed "trajectories"), and random
// programs for the misses. Everything is seeded and deterministic.
#include <cstdint>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "grpvss/cell/load_cell.hpp"
#include "grpvss/certify/robot_cell.hpp"
#include "grpvss/certify/verifier.hpp"
#include "grpvss/model/path_program.hpp"
#include "grpvss/motion/kinematics_access.hpp"

namespace grpvss::bench {

enum class BenchRobot { kUr5e = 0, kPanda = 1, kSixAxis = 2 };
const char* robot_name(BenchRobot robot);
BenchRobot robot_from_name(const std::string& name);

/// The cell file's text: the robot (absolute paths) and `obstacles` generated obstacles
/// (seeded; none within 8 cm of the robot at home), tolerance in metres. Of the obstacles
/// within the robot's reach, every `thin_every`-th is thin (a 2 mm plate or a 3 mm rod).
std::string bench_cell_yaml(BenchRobot robot, int obstacles, double tolerance_m,
                            int thin_every = 4);

/// A loaded cell with its certified RobotCell and what a verify() call needs.
struct BenchCell {
  cell::LoadedCell loaded;
  certify::VerificationSetup setup;
  motion::KinematicsAccess kinematics;
  std::unique_ptr<certify::RobotCell> cell;
};
/// Loads the cell (through a file in the temporary directory) and builds the RobotCell.
std::unique_ptr<BenchCell> make_bench_cell(BenchRobot robot, int obstacles, double tolerance_m,
                                           int thin_every = 4);

/// A random PTP program of `waypoints` segments from the robot's home; each segment is
/// proved CLEAR by the certified verifier before it is kept (rejection sampling, seeded).
PathProgram clear_program(BenchCell& bench, int waypoints, std::uint32_t seed);

/// A random PTP program (no rejection): the misses' ground truth is the verifier's verdict.
PathProgram random_program(const BenchCell& bench, int waypoints, double max_step_deg,
                           std::uint32_t seed);

/// The program as a path file with a cell (degrees, deg/s), readable by io::read_path_file.
std::string path_file_text(const PathProgram& program);

/// Certified verification of `program` on the bench cell.
certify::VerificationRun verify_program(const BenchCell& bench, const PathProgram& program);

}  // namespace grpvss::bench

// grpvss_fcl_peer: the FCL peer as a whole process, for scripts/bench-robots.py
// (docs/performance.md#real-robots-and-fcl).
//
//   grpvss_fcl_peer generate DIR ROBOT OBSTACLES
//       writes DIR/ROBOT-OBSTACLES.yaml (Delta = 5 mm) and DIR/ROBOT-OBSTACLES-W.txt for
//       W = 10 and 100 waypoints: the benchmark's cells and clear programs, as files.
//   grpvss_fcl_peer check (--cell CELL | --robot ROBOT --env ENV) --path PATH
//                         [--tolerance DELTA] [--peer sampled|degree|ca]
//       reads the same inputs as `grpvss verify` (the project's readers), plans the same
//       trajectory, and checks it with FCL: sampled at Delta/4 (default), at 1 degree, or by
//       conservative advancement. Prints COLLISION or FREE; exit code 1 or 0 (2: bad input).
#include <cstdio>
#include <exception>
#include <fstream>
#include <map>
#include <string>

#include "grpvss/cell/load_cell.hpp"
#include "grpvss/io/environment_file.hpp"
#include "grpvss/io/path_file.hpp"
#include "grpvss/io/robot_file.hpp"
#include "grpvss/motion/kinematics_adapter.hpp"
#include "grpvss/motion/trajectory.hpp"
#include "bench/robots/bench_cells.hpp"
#include "bench/robots/fcl_peer.hpp"

namespace {

using namespace grpvss;

int generate(const std::string& directory, const std::string& robot_name, int obstacles) {
  const bench::BenchRobot robot = bench::robot_from_name(robot_name);
  const std::string stem = directory + "/" + robot_name + "-" + std::to_string(obstacles);
  std::ofstream(stem + ".yaml") << bench::bench_cell_yaml(robot, obstacles, 0.005);
  auto cell = bench::make_bench_cell(robot, obstacles, 0.005);
  for (int waypoints : {10, 100}) {
    // Same seed as tests/bench/robots_fcl_bench.cpp (kProgramSeed + waypoints).
    const PathProgram program = bench::clear_program(*cell, waypoints, 22 + waypoints);
    std::ofstream(stem + "-" + std::to_string(waypoints) + ".txt")
        << bench::path_file_text(program);
  }
  return 0;
}

int check(std::map<std::string, std::string> options) {
  RobotModel robot;
  Environment environment;
  double tolerance = options.count("--tolerance") ? std::stod(options["--tolerance"]) : 0.0;
  std::string label = options["--robot"];
  if (options.count("--cell")) {
    cell::LoadedCell loaded = cell::load_cell(options["--cell"]);
    robot = std::move(loaded.robot);
    environment = std::move(loaded.environment);
    if (tolerance == 0.0) tolerance = loaded.tolerance;
    label = options["--cell"];
  } else {
    robot = io::read_robot_file(options["--robot"]);
    environment = io::read_environment_file(options["--env"]);
  }
  if (!(tolerance > 0.0)) throw std::invalid_argument("--tolerance DELTA (> 0) is needed");
  const PathProgram program = io::read_path_file(options["--path"], robot);
  const auto access = motion::make_kinematics_access(robot, motion::select_ik({}, robot, label));
  const auto trajectory = motion::Trajectory::plan(robot, program, access, {});
  bench::FclScene scene(robot, environment);
  const std::string peer = options.count("--peer") ? options["--peer"] : "sampled";
  bench::PeerResult result;
  if (peer == "sampled") {
    result = scene.sampled(trajectory, tolerance / 4, false);
  } else if (peer == "degree") {
    result = scene.sampled(trajectory, 3.14159265358979323846 / 180, true);
  } else if (peer == "ca") {
    result = scene.conservative_advancement(trajectory);
  } else {
    throw std::invalid_argument("--peer sampled|degree|ca");
  }
  std::printf("%s (%ld queries)\n", result.collision ? "COLLISION" : "FREE",
              result.configurations);
  return result.collision ? 1 : 0;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    const std::string command = argc > 1 ? argv[1] : "";
    if (command == "generate" && argc == 5) return generate(argv[2], argv[3], std::stoi(argv[4]));
    if (command == "check") {
      std::map<std::string, std::string> options;
      for (int i = 2; i + 1 < argc; i += 2) options[argv[i]] = argv[i + 1];
      return check(options);
    }
    std::fprintf(stderr, "usage: grpvss_fcl_peer generate DIR ROBOT OBSTACLES | check ...\n");
  } catch (const std::exception& error) {
    std::fprintf(stderr, "grpvss_fcl_peer: %s\n", error.what());
  }
  return 2;
}

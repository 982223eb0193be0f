// Reading speed of the thesis input files (no thesis counterpart: Table 3 does not time input).

#include <fstream>
#include <sstream>
#include <string>

#include <benchmark/benchmark.h>

#include "io/affine_dimension.hpp"
#include "grpvss/io/environment_file.hpp"
#include "grpvss/io/robot_file.hpp"

namespace {

std::string sample_text(const std::string& name) {
  std::ifstream stream(std::string(GRPVSS_SOURCE_DIR) + "/data/ibm7545/" + name);
  std::ostringstream buffer;
  buffer << stream.rdbuf();
  return buffer.str();
}

void BM_ParseIbm7545RobotFile(benchmark::State& state) {
  const std::string text = sample_text("robot.txt");
  for (auto _ : state) {
    benchmark::DoNotOptimize(grpvss::io::parse_robot_file(text, "robot.txt"));
  }
  state.SetItemsProcessed(state.iterations() * 176);  // points
}
BENCHMARK(BM_ParseIbm7545RobotFile);

/// An environment of `hulls` copies of the thesis's first obstacle (16 points each).
void BM_ParseLargeEnvironment(benchmark::State& state) {
  const std::string sample = sample_text("environment.txt");
  const std::size_t first_hull = sample.find("15,15,15");
  const std::size_t second_hull = sample.find("-12,10,15");
  const std::string hull = sample.substr(first_hull, second_hull - first_hull);
  std::string text = "90.\n5.\n" + std::to_string(state.range(0)) + "\n";
  for (int h = 0; h < state.range(0); ++h) text += hull;
  for (auto _ : state) {
    benchmark::DoNotOptimize(grpvss::io::parse_environment_file(text, "large.txt"));
  }
  state.SetItemsProcessed(state.iterations() * state.range(0) * 16);
  state.SetBytesProcessed(state.iterations() * static_cast<int64_t>(text.size()));
}
BENCHMARK(BM_ParseLargeEnvironment)->Arg(1000)->Arg(10000);

/// The exact flatness test on a hull whose first 8 points are coplanar (the thesis shape).
void BM_AffineDimensionThesisHull(benchmark::State& state) {
  const grpvss::RobotModel robot = grpvss::io::parse_robot_file(sample_text("robot.txt"), "r");
  const auto& points = robot.links[0].hulls[0].points;
  for (auto _ : state) benchmark::DoNotOptimize(grpvss::io::affine_dimension(points));
}
BENCHMARK(BM_AffineDimensionThesisHull);

}  // namespace

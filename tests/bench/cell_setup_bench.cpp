// What a `grpvss verify` process pays before its first step on a real robot
// (docs/performance.md#cell-set-up): reading the cell (URDF, meshes, shapes: load_cell) and
// building the certified RobotCell, cold (every link offset built) and from a warm set-up
// cache (every offset re-checked exactly); beside it the FCL peer's scene from the same loaded
// cell. Args: robot (0 UR5e, 1 Panda, 2 six-axis), obstacles.
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>

#include <unistd.h>

#include <benchmark/benchmark.h>

#include "grpvss/cell/load_cell.hpp"
#include "grpvss/certify/robot_cell.hpp"
#include "grpvss/certify/setup_cache.hpp"
#include "grpvss/certify/verifier.hpp"
#include "robots/bench_cells.hpp"
#ifdef GRPVSS_HAVE_FCL
#include "robots/fcl_peer.hpp"
#endif

namespace {

using grpvss::bench::BenchRobot;

// The bench cell's YAML in a file of its own, removed at exit.
struct SetupBenchCellFile {
  SetupBenchCellFile(int robot, int obstacles)
      : path((std::filesystem::temp_directory_path() /
              ("grpvss-bench-setup-" + std::to_string(::getpid()) + "-" + std::to_string(robot) +
               "-" + std::to_string(obstacles) + ".yaml"))
                 .string()) {
    std::ofstream(path) << grpvss::bench::bench_cell_yaml(static_cast<BenchRobot>(robot),
                                                          obstacles, 0.005);
  }
  ~SetupBenchCellFile() { std::filesystem::remove(path); }
  std::string path;
};

grpvss::certify::CellSettings setup_bench_settings(const grpvss::cell::LoadedCell& loaded) {
  grpvss::certify::SetupRequest request;
  request.tolerance = loaded.tolerance;
  return grpvss::certify::resolve_setup(request).cell;
}

void setup_bench_label(benchmark::State& state) {
  state.SetLabel(grpvss::bench::robot_name(static_cast<BenchRobot>(state.range(0))));
}

// Reading the cell: URDF, link meshes and their hulls, obstacle shapes and meshes.
void BM_CellLoad(benchmark::State& state) {
  const SetupBenchCellFile file(static_cast<int>(state.range(0)), static_cast<int>(state.range(1)));
  for (auto _ : state) {
    grpvss::cell::LoadedCell loaded = grpvss::cell::load_cell(file.path);
    benchmark::DoNotOptimize(loaded);
  }
  setup_bench_label(state);
}

// The certified cell with every link offset built (a cold process, or --no-cache).
void BM_CellRobotCellCold(benchmark::State& state) {
  const SetupBenchCellFile file(static_cast<int>(state.range(0)), static_cast<int>(state.range(1)));
  const grpvss::cell::LoadedCell loaded = grpvss::cell::load_cell(file.path);
  const grpvss::certify::CellSettings settings = setup_bench_settings(loaded);
  for (auto _ : state) {
    grpvss::certify::RobotCell cell(loaded.robot, loaded.environment, settings);
    benchmark::DoNotOptimize(cell);
  }
  setup_bench_label(state);
}

// The same from a warm set-up cache: read the entry, re-check every offset exactly.
void BM_CellRobotCellFromCache(benchmark::State& state) {
  const SetupBenchCellFile file(static_cast<int>(state.range(0)), static_cast<int>(state.range(1)));
  const grpvss::cell::LoadedCell loaded = grpvss::cell::load_cell(file.path);
  const grpvss::certify::CellSettings settings = setup_bench_settings(loaded);
  const std::string directory = file.path + ".cache";
  const grpvss::certify::SetupCacheOptions options{directory, "bench"};
  {
    grpvss::certify::SetupCache cold(options);
    grpvss::certify::RobotCell warm_up(loaded.robot, loaded.environment, settings, &cold);
  }
  for (auto _ : state) {
    grpvss::certify::SetupCache cache(options);
    grpvss::certify::RobotCell cell(loaded.robot, loaded.environment, settings, &cache);
    if (!cache.loaded() || !cache.notes().empty()) state.SkipWithError("the entry was not used");
    benchmark::DoNotOptimize(cell);
  }
  std::filesystem::remove_all(directory);
  setup_bench_label(state);
}

#ifdef GRPVSS_HAVE_FCL
// The FCL peer's set-up from the same loaded cell: a BVH model per link hull and obstacle,
// the obstacles' DynamicAABBTree.
void BM_CellFclScene(benchmark::State& state) {
  const SetupBenchCellFile file(static_cast<int>(state.range(0)), static_cast<int>(state.range(1)));
  const grpvss::cell::LoadedCell loaded = grpvss::cell::load_cell(file.path);
  for (auto _ : state) {
    auto scene = std::make_unique<grpvss::bench::FclScene>(loaded.robot, loaded.environment);
    benchmark::DoNotOptimize(scene);
  }
  setup_bench_label(state);
}
BENCHMARK(BM_CellFclScene)->Args({0, 100})->Args({1, 100})->Args({2, 100})->Unit(benchmark::kMillisecond);
#endif

BENCHMARK(BM_CellLoad)->Args({0, 100})->Args({1, 100})->Args({2, 100})->Unit(benchmark::kMillisecond);
BENCHMARK(BM_CellRobotCellCold)->Args({0, 100})->Args({1, 100})->Args({2, 100})->Unit(benchmark::kMillisecond);
BENCHMARK(BM_CellRobotCellFromCache)->Args({0, 100})->Args({1, 100})->Args({2, 100})->Unit(benchmark::kMillisecond);

}  // namespace

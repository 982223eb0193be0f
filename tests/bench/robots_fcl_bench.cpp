// Real robots against FCL (docs/performance.md#real-robots-and-fcl, issue #22 point 1): the
// UR5e and the Panda of ../shared/robots and the six-axis robot of data/sixaxis among 10,
// 100 and 1,000 generated obstacles (tests/bench/robots/bench_cells.cpp), with the FCL peers
// of tests/bench/robots/fcl_peer.cpp on the same geometry and the same forward kinematics.
//
// Arguments: robot (0 UR5e, 1 Panda, 2 six-axis), obstacles, waypoints, Delta in mm.
// "Trajectory" = a PTP path program of 10 or 100 joint waypoints from home whose every
// segment the certified verifier proved CLEAR when it was generated (so no peer stops early).
// FCL peers get the verifier's planned trajectory (motion::Trajectory, planned outside the
// timed loop); the certified verifier plans inside it.
#include <algorithm>
#include <map>
#include <memory>
#include <tuple>

#include <benchmark/benchmark.h>

#include "certify/cell_probe.hpp"
#include "grpvss/certify/configuration_check.hpp"
#include "grpvss/motion/trajectory.hpp"
#include "bench/robots/bench_cells.hpp"
#ifdef GRPVSS_HAVE_FCL
#include "bench/robots/fcl_peer.hpp"
#endif

namespace {

using grpvss::bench::BenchCell;
using grpvss::bench::BenchRobot;

constexpr std::uint32_t kProgramSeed = 22;

BenchCell& bench_cell(int robot, int obstacles, int delta_mm, int thin_every = 4) {
  static std::map<std::tuple<int, int, int, int>, std::unique_ptr<BenchCell>> cells;
  auto& slot = cells[{robot, obstacles, delta_mm, thin_every}];
  if (!slot) {
    slot = grpvss::bench::make_bench_cell(static_cast<BenchRobot>(robot), obstacles,
                                          delta_mm * 1e-3, thin_every);
  }
  return *slot;
}

// The clear program of (robot, obstacles, waypoints), generated once on the Delta = 5 mm cell
// (a path proved CLEAR for 5 mm is CLEAR for 1 mm too: same nominal robot).
const grpvss::PathProgram& clear_program(int robot, int obstacles, int waypoints) {
  static std::map<std::tuple<int, int, int>, grpvss::PathProgram> programs;
  const auto key = std::make_tuple(robot, obstacles, waypoints);
  auto found = programs.find(key);
  if (found == programs.end()) {
    found = programs
                .emplace(key, grpvss::bench::clear_program(bench_cell(robot, obstacles, 5),
                                                           waypoints, kProgramSeed + waypoints))
                .first;
  }
  return found->second;
}

grpvss::motion::Trajectory planned(const BenchCell& bench, const grpvss::PathProgram& program) {
  return grpvss::motion::Trajectory::plan(bench.loaded.robot, program, bench.kinematics,
                                          bench.setup.run.motion);
}

// 64 configurations along the 10-waypoint clear trajectory, equally spaced in time.
std::vector<Eigen::VectorXd> configurations(int robot, int obstacles) {
  BenchCell& bench = bench_cell(robot, obstacles, 5);
  const auto trajectory = planned(bench, clear_program(robot, obstacles, 10));
  std::vector<Eigen::VectorXd> qs;
  for (int i = 0; i < 64; ++i) qs.push_back(*trajectory.joints_at(trajectory.duration() * i / 63));
  return qs;
}

void per_item(benchmark::State& state, double items_per_iteration, const char* name) {
  state.counters[name] = benchmark::Counter(items_per_iteration * state.iterations(),
                                            benchmark::Counter::kIsRate |
                                                benchmark::Counter::kInvert);
}

void robot_label(benchmark::State& state) {
  state.SetLabel(grpvss::bench::robot_name(static_cast<BenchRobot>(state.range(0))));
}

// One certified configuration: CellProbe::probe (every link hull placed, its offset decided
// against the candidates of the broadphase, a certified clearance per hull). Args: robot,
// obstacles. Counters: per_config; hulls, hull_vertices and offset_vertices (summed over the
// robot's link hulls and their tolerance offsets: what each probe places and scans).
void BM_RobotConfigurationGrpvss(benchmark::State& state) {
  const auto qs = configurations(state.range(0), state.range(1));
  BenchCell& bench = bench_cell(state.range(0), state.range(1), 5);
  grpvss::certify::CellProbe probe(*bench.cell);
  grpvss::certify::ProbeResult out;
  for (auto _ : state) {
    for (const auto& q : qs) {
      probe.probe(q, false, out);
      benchmark::DoNotOptimize(out);
    }
  }
  per_item(state, qs.size(), "per_config");
  double hull_vertices = 0, offset_vertices = 0;
  for (const auto& hull : bench.cell->hulls()) {
    hull_vertices += hull.raw_L.size();
    offset_vertices += hull.expanded_L.size();
  }
  state.counters["hulls"] = bench.cell->hulls().size();
  state.counters["hull_vertices"] = hull_vertices;
  state.counters["offset_vertices"] = offset_vertices;
  robot_label(state);
}

// The 36 trajectory cases: 3 robots x {10, 100, 1000} obstacles x {10, 100} waypoints x
// Delta {1, 5} mm.
void trajectory_args(benchmark::internal::Benchmark* b) {
  for (int robot : {0, 1, 2}) {
    for (int obstacles : {10, 100, 1000}) {
      for (int waypoints : {10, 100}) {
        for (int delta : {1, 5}) b->Args({robot, obstacles, waypoints, delta});
      }
    }
  }
}

void configuration_args(benchmark::internal::Benchmark* b) {
  for (int robot : {0, 1, 2}) {
    for (int obstacles : {10, 100, 1000}) b->Args({robot, obstacles});
  }
}

BENCHMARK(BM_RobotConfigurationGrpvss)->Apply(configuration_args)->Unit(benchmark::kMicrosecond);

// The certified verdict of one configuration (ConfigurationCheck::check: FCL's boolean
// question with the certified mode's guarantee), same 64 configurations. Counters: per_config;
// clear (how many of the 64 are CLEAR: all of them, on a certified-clear trajectory).
void BM_RobotConfigurationCheckGrpvss(benchmark::State& state) {
  const auto qs = configurations(state.range(0), state.range(1));
  BenchCell& bench = bench_cell(state.range(0), state.range(1), 5);
  grpvss::certify::ConfigurationCheck check(*bench.cell);
  int clear = 0;
  for (auto _ : state) {
    clear = 0;
    for (const auto& q : qs) clear += check.check(q).verdict == grpvss::certify::Verdict::kClear;
  }
  if (clear != static_cast<int>(qs.size())) state.SkipWithError("a configuration of a certified-clear trajectory is not CLEAR");
  state.counters["clear"] = clear;
  per_item(state, qs.size(), "per_config");
  robot_label(state);
}
BENCHMARK(BM_RobotConfigurationCheckGrpvss)->Apply(configuration_args)->Unit(benchmark::kMicrosecond);

// A whole certified trajectory on a prebuilt cell (verify(cell, ...): planning, the march,
// the certificate). Counters: steps, verdict (0 = CLEAR), per_segment. With 10 waypoints and
// Delta 5 mm on the UR5e this is the batch-warm rate (programs/s = 1 / time).
void BM_RobotTrajectoryGrpvss(benchmark::State& state) {
  const auto& program = clear_program(state.range(0), state.range(1), state.range(2));
  BenchCell& bench = bench_cell(state.range(0), state.range(1), state.range(3));
  grpvss::certify::VerificationRun run;
  for (auto _ : state) {
    run = grpvss::bench::verify_program(bench, program);
    benchmark::DoNotOptimize(run);
  }
  state.counters["steps"] = run.result.steps.size();
  state.counters["verdict"] = static_cast<int>(run.result.verdict);
  per_item(state, program.segments.size(), "per_segment");
  robot_label(state);
}
BENCHMARK(BM_RobotTrajectoryGrpvss)->Apply(trajectory_args)->Unit(benchmark::kMicrosecond);

#ifdef GRPVSS_HAVE_FCL

grpvss::bench::FclScene& fcl_scene(int robot, int obstacles, int thin_every = 4) {
  static std::map<std::tuple<int, int, int>, std::unique_ptr<grpvss::bench::FclScene>> scenes;
  auto& slot = scenes[{robot, obstacles, thin_every}];
  if (!slot) {
    const BenchCell& bench = bench_cell(robot, obstacles, 5, thin_every);
    slot = std::make_unique<grpvss::bench::FclScene>(bench.loaded.robot,
                                                     bench.loaded.environment);
  }
  return *slot;
}

// FCL collide() of every link hull against the obstacles' DynamicAABBTree, same 64
// configurations as BM_RobotConfigurationGrpvss.
void BM_RobotConfigurationFcl(benchmark::State& state) {
  const auto qs = configurations(state.range(0), state.range(1));
  auto& scene = fcl_scene(state.range(0), state.range(1));
  int hits = 0;
  for (auto _ : state) {
    hits = 0;
    for (const auto& q : qs) hits += scene.collides(q);
  }
  if (hits != 0) state.SkipWithError("FCL finds a contact on a certified-clear trajectory");
  per_item(state, qs.size(), "per_config");
  robot_label(state);
}
BENCHMARK(BM_RobotConfigurationFcl)->Apply(configuration_args)->Unit(benchmark::kMicrosecond);

enum class Peer { kSampledQuarterDelta, kOneDegree, kConservativeAdvancement };

grpvss::bench::PeerResult run_peer(grpvss::bench::FclScene& scene,
                                   const grpvss::motion::Trajectory& trajectory, Peer peer,
                                   double delta_m) {
  switch (peer) {
    case Peer::kSampledQuarterDelta: return scene.sampled(trajectory, delta_m / 4, false);
    case Peer::kOneDegree: return scene.sampled(trajectory, 3.14159265358979323846 / 180, true);
    case Peer::kConservativeAdvancement: return scene.conservative_advancement(trajectory);
  }
  return {};
}

void measure_peer(benchmark::State& state, Peer peer) {
  const auto& program = clear_program(state.range(0), state.range(1), state.range(2));
  const BenchCell& bench = bench_cell(state.range(0), state.range(1), 5);
  const auto trajectory = planned(bench, program);
  auto& scene = fcl_scene(state.range(0), state.range(1));
  grpvss::bench::PeerResult result;
  for (auto _ : state) {
    result = run_peer(scene, trajectory, peer, state.range(3) * 1e-3);
    benchmark::DoNotOptimize(result);
  }
  state.counters["queries"] = result.configurations;
  state.counters["collision"] = result.collision;
  per_item(state, program.segments.size(), "per_segment");
  robot_label(state);
}

// FCL discrete sampling, no hull vertex moving more than Delta/4 between samples.
void BM_RobotTrajectoryFclSampled(benchmark::State& state) {
  measure_peer(state, Peer::kSampledQuarterDelta);
}
BENCHMARK(BM_RobotTrajectoryFclSampled)->Apply(trajectory_args)->Unit(benchmark::kMicrosecond);

void one_delta_args(benchmark::internal::Benchmark* b) {
  for (int robot : {0, 1, 2}) {
    for (int obstacles : {10, 100, 1000}) {
      for (int waypoints : {10, 100}) b->Args({robot, obstacles, waypoints, 5});
    }
  }
}

// FCL discrete sampling at 1 degree per step (Delta does not enter).
void BM_RobotTrajectoryFclOneDegree(benchmark::State& state) {
  measure_peer(state, Peer::kOneDegree);
}
BENCHMARK(BM_RobotTrajectoryFclOneDegree)->Apply(one_delta_args)->Unit(benchmark::kMicrosecond);

// FCL continuousCollide, conservative advancement, screw motion per link hull and segment.
void BM_RobotTrajectoryFclConservativeAdvancement(benchmark::State& state) {
  measure_peer(state, Peer::kConservativeAdvancement);
}
BENCHMARK(BM_RobotTrajectoryFclConservativeAdvancement)
    ->Apply(one_delta_args)
    ->Unit(benchmark::kMicrosecond);

// The misses: 50 random UR5e PTP programs (3 segments of up to 60 deg per joint, seeded) in
// the 100-obstacle cell; the certified verifier's verdict is the ground truth. Counters:
// collision (an obstacle hit) / self_collision (only self-contacts: the peers check no self
// pairs, so these are not scored) / clear / other (within tolerance, undecided, error) paths by
// the verifier, and
// per peer the COLLISION paths it calls free (missed_*) and the CLEAR paths it calls
// colliding (false_*). Args: Delta in mm; 4 = the benchmark cell (every fourth obstacle
// within reach thin), 1 = the same cell with every obstacle within reach thin (2 mm plates,
// 3 mm rods). One iteration; the time is the whole study.
void BM_RobotMissesUr5e(benchmark::State& state) {
  const int delta_mm = state.range(0);
  const int thin_every = state.range(1);
  BenchCell& bench = bench_cell(0, 100, delta_mm, thin_every);
  auto& scene = fcl_scene(0, 100, thin_every);
  std::map<std::string, double> counts;
  for (auto _ : state) {
    counts.clear();
    for (std::uint32_t seed = 0; seed < 50; ++seed) {
      const auto program = grpvss::bench::random_program(bench, 3, 60.0, 1000 + seed);
      const auto run = grpvss::bench::verify_program(bench, program);
      const auto verdict = run.result.verdict;
      // The peers check the robot against the obstacles only (no self pairs): a path whose only
      // contacts are self-contacts is counted apart and not scored.
      const auto& episodes = run.result.interference_episodes;
      const bool hits_an_obstacle =
          std::any_of(episodes.begin(), episodes.end(),
                      [](const auto& episode) { return episode.first_collision_step.has_value(); });
      const bool self_only = verdict == grpvss::certify::Verdict::kCollision && !hits_an_obstacle;
      const bool collision = verdict == grpvss::certify::Verdict::kCollision && !self_only;
      const bool clear = verdict == grpvss::certify::Verdict::kClear;
      counts[collision ? "collision" : self_only ? "self_collision" : clear ? "clear" : "other"] += 1;
      if (self_only) continue;
      const auto trajectory = planned(bench, program);
      const std::pair<const char*, Peer> peers[] = {
          {"sampled", Peer::kSampledQuarterDelta},
          {"one_degree", Peer::kOneDegree},
          {"ca", Peer::kConservativeAdvancement}};
      for (const auto& [name, peer] : peers) {
        const bool hit = run_peer(scene, trajectory, peer, delta_mm * 1e-3).collision;
        if (collision && !hit) counts[std::string("missed_") + name] += 1;
        if (clear && hit) counts[std::string("false_") + name] += 1;
      }
    }
  }
  for (const char* key : {"collision", "self_collision", "clear", "other", "missed_sampled",
                          "missed_one_degree",
                          "missed_ca", "false_sampled", "false_one_degree", "false_ca"}) {
    state.counters[key] = counts[key];
  }
}
BENCHMARK(BM_RobotMissesUr5e)
    ->Args({1, 4})
    ->Args({5, 4})
    ->Args({1, 1})
    ->Args({5, 1})
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond);

#endif  // GRPVSS_HAVE_FCL

}  // namespace

/// \file
/// \brief Timings of the exact geometry core on IBM 7545 hulls (random rotations, fixed seed).

#include <benchmark/benchmark.h>

#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "grpvss/exact/convex_polytope.hpp"
#include "grpvss/exact/exact_contact.hpp"
#include "grpvss/exact/minkowski_offset.hpp"
#include "grpvss/geometry/separation_witness.hpp"

namespace {

using Points = std::vector<Eigen::Vector3d>;
using namespace grpvss::geometry;

std::vector<Points> hulls() {
  std::vector<Points> out;
  Points current;
  for (const char* name : {"robot.txt", "environment.txt"}) {
    std::ifstream in(std::string(GRPVSS_SOURCE_DIR) + "/data/ibm7545/" + name);
    std::string line;
    while (std::getline(in, line)) {
      std::stringstream ss(line);
      std::string field;
      std::vector<double> v;
      while (std::getline(ss, field, ',')) v.push_back(std::stod(field));
      if (v.size() != 3) continue;
      current.emplace_back(v[0], v[1], v[2]);
      if (current.size() == 16) {
        out.push_back(current);
        current.clear();
      }
    }
  }
  return out;
}

Points placed(const Points& p, std::mt19937_64& rng, double spread) {
  std::normal_distribution<double> g(0.0, 1.0);
  std::uniform_real_distribution<double> u(-spread, spread);
  Eigen::Quaterniond q(g(rng), g(rng), g(rng), g(rng));
  q.normalize();
  const Eigen::Vector3d t(u(rng), u(rng), u(rng));
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (const auto& x : p) mean += x;
  mean /= static_cast<double>(p.size());
  Points out;
  for (const auto& x : p) out.push_back(q * (x - mean) + t);
  return out;
}

struct PairSet {
  std::vector<std::pair<Points, Points>> pairs;
  explicit PairSet(double spread) {
    std::mt19937_64 rng(1988);
    const auto h = hulls();
    for (int i = 0; i < 64; ++i) {
      pairs.emplace_back(placed(h[rng() % h.size()], rng, 0.0),
                         placed(h[rng() % h.size()], rng, spread));
    }
  }
};

void BM_HullFromPointsRotated(benchmark::State& state) {
  std::mt19937_64 rng(7);
  const Points p = placed(hulls()[0], rng, 5.0);
  for (auto _ : state) benchmark::DoNotOptimize(ConvexPolytope::from_points(p));
}
BENCHMARK(BM_HullFromPointsRotated);

void BM_ClassifyExact(benchmark::State& state) {
  const PairSet set(static_cast<double>(state.range(0)));
  std::size_t i = 0;
  for (auto _ : state) {
    const auto& pr = set.pairs[i++ % set.pairs.size()];
    benchmark::DoNotOptimize(classify_exact(pr.first, pr.second));
  }
}
// spread 40: mostly separated; spread 4: mostly overlapping.
BENCHMARK(BM_ClassifyExact)->Arg(40)->Arg(4);

void BM_InterferencePointsOverlapping(benchmark::State& state) {
  const PairSet set(4.0);
  std::size_t i = 0;
  for (auto _ : state) {
    const auto& pr = set.pairs[i++ % set.pairs.size()];
    benchmark::DoNotOptimize(interference_points(pr.first, pr.second));
  }
}
BENCHMARK(BM_InterferencePointsOverlapping);

void BM_ExactSeparationWitness(benchmark::State& state) {
  const PairSet set(60.0);
  std::size_t i = 0;
  for (auto _ : state) {
    const auto& pr = set.pairs[i++ % set.pairs.size()];
    benchmark::DoNotOptimize(exact_separation_witness(pr.first, pr.second));
  }
}
BENCHMARK(BM_ExactSeparationWitness);

void BM_CheckWitnessExactly(benchmark::State& state) {
  const PairSet set(60.0);
  std::vector<std::pair<SeparationWitness, double>> w;
  for (const auto& pr : set.pairs) {
    const auto s = exact_separation_witness(pr.first, pr.second);
    w.emplace_back(s ? *s : SeparationWitness{{1, 0, 0}, 0, 0}, s ? certified_lower_bound(*s) : 0);
  }
  std::size_t i = 0;
  for (auto _ : state) {
    const std::size_t k = i++ % set.pairs.size();
    benchmark::DoNotOptimize(
        check_witness_exactly(set.pairs[k].first, set.pairs[k].second, w[k].first, w[k].second));
  }
}
BENCHMARK(BM_CheckWitnessExactly);

void BM_MinkowskiOffset(benchmark::State& state) {
  std::mt19937_64 rng(3);
  const ConvexPolytope hull = ConvexPolytope::from_points(placed(hulls()[3], rng, 5.0));
  const auto shape = state.range(0) == 0 ? OffsetShape::kCube : OffsetShape::kRhombicuboctahedron;
  for (auto _ : state) benchmark::DoNotOptimize(minkowski_offset(hull, 0.5, shape));
}
BENCHMARK(BM_MinkowskiOffset)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

}  // namespace

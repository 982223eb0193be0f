// Expanding one IBM 7545 hull: the thesis's float algorithm (Table 3: 0.016 s on an IBM 4341)
// against the exactly verified Minkowski offsets. Results: docs/expansion-audit.md.
#include <string>

#include <benchmark/benchmark.h>

#include "grpvss/exact/convex_polytope.hpp"
#include "grpvss/exact/minkowski_offset.hpp"
#include "grpvss/geometry/thesis_expansion.hpp"
#include "grpvss/io/robot_file.hpp"

namespace {

const grpvss::HullPoints& base_octagon() {
  static const grpvss::RobotModel robot =
      grpvss::io::read_robot_file(std::string(GRPVSS_SOURCE_DIR) + "/data/ibm7545/robot.txt");
  return robot.links[0].hulls[0];  // link 0 hull 0: the 16-vertex base octagon
}

void BM_ThesisExpansionSingle(benchmark::State& state) {
  for (auto _ : state) {
    benchmark::DoNotOptimize(grpvss::geometry::expand_prism_as_thesis<float>(base_octagon(), 0.5));
  }
}
BENCHMARK(BM_ThesisExpansionSingle);

void BM_ThesisExpansionDouble(benchmark::State& state) {
  for (auto _ : state) {
    benchmark::DoNotOptimize(grpvss::geometry::expand_prism_as_thesis<double>(base_octagon(), 0.5));
  }
}
BENCHMARK(BM_ThesisExpansionDouble);

void BM_ExactOffset(benchmark::State& state) {
  const auto shape = static_cast<grpvss::geometry::OffsetShape>(state.range(0));
  const auto hull = grpvss::geometry::ConvexPolytope::from_points(base_octagon().points);
  for (auto _ : state) {
    benchmark::DoNotOptimize(grpvss::geometry::minkowski_offset(hull, 0.5, shape));
  }
  state.SetLabel(shape == grpvss::geometry::OffsetShape::kCube ? "cube" : "rhombicuboctahedron");
}
BENCHMARK(BM_ExactOffset)
    ->Arg(static_cast<int>(grpvss::geometry::OffsetShape::kCube))
    ->Arg(static_cast<int>(grpvss::geometry::OffsetShape::kRhombicuboctahedron));

}  // namespace

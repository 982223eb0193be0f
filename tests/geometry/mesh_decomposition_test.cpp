#include "grpvss/exact/mesh_decomposition.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <set>
#include <tuple>
#include <string>

#include "geometry/mesh_fixtures.hpp"
#include "geometry/mesh_reference.hpp"
#include "grpvss/common/input_error.hpp"
#include "grpvss/exact/convex_polytope.hpp"
#include "support/geometry_reference.hpp"

namespace grpvss::geometry {
namespace {

namespace meshes = testing::meshes;

ConvexPieces decompose(const TriangleMesh& mesh, DecomposeMode mode, double thickness = 0.0) {
  DecompositionOptions options;
  options.mode = mode;
  options.flat_thickness = thickness;
  return decompose_mesh(mesh, options);
}

std::vector<double> sorted_volumes(const ConvexPieces& result) {
  std::vector<double> v;
  for (const auto& piece : result.pieces) v.push_back(ConvexPolytope::from_points(piece).volume());
  std::sort(v.begin(), v.end());
  return v;
}

std::vector<std::string> texts(const ConvexPieces& result) {
  std::vector<std::string> t;
  for (const auto& w : result.warnings) {
    EXPECT_EQ(w.line, 0);
    t.push_back(w.text);
  }
  return t;
}

/// Same point sets (any order).
bool same_points(const std::vector<Eigen::Vector3d>& a, const std::vector<Eigen::Vector3d>& b) {
  std::set<std::tuple<double, double, double>> sa, sb;
  for (const auto& v : a) sa.emplace(v.x(), v.y(), v.z());
  for (const auto& v : b) sb.emplace(v.x(), v.y(), v.z());
  return sa == sb;
}

bool in_some_piece(const ConvexPieces& result, const Eigen::Vector3d& x) {
  for (const auto& piece : result.pieces) {
    // Outside the bounding box (exact comparisons) is outside the hull: skip the hull.
    Eigen::Vector3d lo = piece.front(), hi = lo;
    for (const auto& v : piece) {
      lo = lo.cwiseMin(v);
      hi = hi.cwiseMax(v);
    }
    if ((x.array() < lo.array()).any() || (x.array() > hi.array()).any()) continue;
    if (testing::point_in_hull_exactly(piece, x)) return true;
  }
  return false;
}

/// Every mesh vertex and every sampled point inside the solid (independent exact ray
/// parity) lies in some piece (independent exact hull). Returns how many samples were inside.
int expect_pieces_contain_solid(const TriangleMesh& mesh, const ConvexPieces& result, int samples) {
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
    EXPECT_TRUE(in_some_piece(result, mesh.vertices[v])) << "vertex " << v;
  }
  std::mt19937_64 rng(4242);
  int inside = 0;
  for (const auto& x : testing::random_box_points(mesh, samples, rng)) {
    if (!testing::inside_by_parity(mesh, x)) continue;
    ++inside;
    EXPECT_TRUE(in_some_piece(result, x)) << x.transpose();
  }
  return inside;
}

TEST(MeshDecomposition, HullModeOfTheLBracketIsOneHullWithHalfAgainItsVolume) {
  const TriangleMesh l = meshes::l_bracket();
  const ConvexPieces result = decompose(l, DecomposeMode::kHull);
  ASSERT_EQ(result.pieces.size(), 1u);
  EXPECT_EQ(result.pieces[0].size(), 10u);  // hull profile (0,0) (4,0) (4,1) (1,3) (0,3), twice
  EXPECT_EQ(sorted_volumes(result), std::vector<double>{18.0});
  ASSERT_TRUE(result.volume_ratio.has_value());
  EXPECT_EQ(*result.volume_ratio, 1.5);  // 18 / 12
  EXPECT_EQ(texts(result),
            std::vector<std::string>{"one convex hull adds 50% volume; consider decompose: parts or exact"});
  EXPECT_EQ(result.warnings[0].file, "l_bracket.stl");
  EXPECT_EQ(result.piece_origins, std::vector<std::string>{"all triangles"});
  EXPECT_GT(expect_pieces_contain_solid(l, result, 300), 50);
}

TEST(MeshDecomposition, HullModeOfTheUFixtureAddsTwoThirds) {
  const ConvexPieces result = decompose(meshes::u_fixture(), DecomposeMode::kHull);
  EXPECT_EQ(sorted_volumes(result), std::vector<double>{30.0});
  EXPECT_DOUBLE_EQ(*result.volume_ratio, 30.0 / 18.0);
  EXPECT_EQ(texts(result),
            std::vector<std::string>{"one convex hull adds 67% volume; consider decompose: parts or exact"});
  // A looser threshold silences the warning.
  DecompositionOptions quiet;
  quiet.warn_volume_ratio = 2.0;
  EXPECT_TRUE(decompose_mesh(meshes::u_fixture(), quiet).warnings.empty());
}

TEST(MeshDecomposition, PartsModeGivesOneHullPerComponent) {
  const TriangleMesh two = meshes::merged(meshes::l_bracket(), meshes::box({6, 0, 0}, {7, 1, 1}));
  const ConvexPieces result = decompose(two, DecomposeMode::kParts);
  EXPECT_EQ(sorted_volumes(result), (std::vector<double>{1.0, 18.0}));
  EXPECT_EQ(result.piece_origins,
            (std::vector<std::string>{"component of triangle 0", "component of triangle 20"}));
  EXPECT_DOUBLE_EQ(*result.volume_ratio, 19.0 / 13.0);
  EXPECT_EQ(texts(result), std::vector<std::string>{
                               "the 2 part hulls add 46% volume; consider decompose: exact"});
  EXPECT_GT(expect_pieces_contain_solid(two, result, 300), 20);
  // hull mode: one hull over both, far larger.
  EXPECT_EQ(decompose(two, DecomposeMode::kHull).pieces.size(), 1u);
}

TEST(MeshDecomposition, ExactModeSplitsTheLBracketIntoVerifiedPiecesOfItsOwnVolume) {
  const TriangleMesh l = meshes::l_bracket();
  const ConvexPieces result = decompose(l, DecomposeMode::kExact);
  // One reflex edge (x = 1, z = 1, along y): CGAL 5.5 walls it off at z = 1 into the foot
  // [0,4]x[0,2]x[0,1] and the upright [0,1]x[0,2]x[1,3].
  ASSERT_EQ(result.pieces.size(), 2u);
  EXPECT_EQ(sorted_volumes(result), (std::vector<double>{4.0, 8.0}));
  EXPECT_TRUE(same_points(result.pieces[0], testing::box({0, 0, 0}, {4, 2, 1})));
  EXPECT_TRUE(same_points(result.pieces[1], testing::box({0, 0, 1}, {1, 2, 3})));
  EXPECT_EQ(*result.volume_ratio, 1.0);
  EXPECT_TRUE(result.warnings.empty()) << texts(result).front();
  EXPECT_EQ(result.piece_origins[0], "exact piece 0 of component of triangle 0");
  for (const auto& piece : result.pieces) {
    EXPECT_EQ(piece.size(), 8u);  // boxes with integer corners: no rounding was needed
    for (const auto& v : piece) EXPECT_EQ(v, v.array().round().matrix());
  }
  EXPECT_GT(expect_pieces_contain_solid(l, result, 400), 80);
}

TEST(MeshDecomposition, ExactModeSplitsTheUFixtureIntoThreePieces) {
  const TriangleMesh u = meshes::u_fixture();
  const ConvexPieces result = decompose(u, DecomposeMode::kExact);
  // The foot [0,5]x[0,2]x[0,1] and the two arms on it.
  ASSERT_EQ(result.pieces.size(), 3u);
  EXPECT_EQ(sorted_volumes(result), (std::vector<double>{4.0, 4.0, 10.0}));
  EXPECT_TRUE(same_points(result.pieces[0], testing::box({0, 0, 0}, {5, 2, 1})));
  EXPECT_TRUE(same_points(result.pieces[1], testing::box({4, 0, 1}, {5, 2, 3})));
  EXPECT_TRUE(same_points(result.pieces[2], testing::box({0, 0, 1}, {1, 2, 3})));
  EXPECT_EQ(*result.volume_ratio, 1.0);
  EXPECT_TRUE(result.warnings.empty());
  EXPECT_GT(expect_pieces_contain_solid(u, result, 400), 80);
}

TEST(MeshDecomposition, ExactModeRoundsRationalPieceVerticesOutward) {
  // The L-bracket with a slanted back edge (-1,0)-(0,3): walls through the reflex edge meet
  // it at non-double points such as x = -2/3.
  const TriangleMesh slanted =
      meshes::extruded({{-1, 0}, {4, 0}, {4, 1}, {1, 1}, {1, 3}, {0, 3}},
                       {{0, 1, 2}, {0, 2, 3}, {0, 3, 4}, {0, 4, 5}}, 2.0, "slanted.stl");
  const ConvexPieces result = decompose(slanted, DecomposeMode::kExact);
  // Cut at z = 1: the foot's top-left corner and the upright's bottom-left corner are
  // (-2/3, y, 1), not doubles. Each is replaced by the two doubles around -2/3; the one
  // nearer the cut's far end lies on an edge and drops out of the hull, the outer one stays.
  ASSERT_EQ(result.pieces.size(), 2u);
  const double below = -0.66666666666666674, above = std::nextafter(below, 0.0);
  ASSERT_LT(testing::Rational(below), testing::Rational(-2) / 3);
  ASSERT_GT(testing::Rational(above), testing::Rational(-2) / 3);
  for (const auto& piece : result.pieces) {
    int outer = 0;
    for (const auto& v : piece) {
      outer += (v.z() == 1.0 && v.x() == below) ? 1 : 0;
      EXPECT_NE(v.x(), above);
    }
    EXPECT_EQ(outer, 2);  // at y = 0 and y = 2
  }
  EXPECT_TRUE(result.warnings.empty());
  ASSERT_TRUE(result.volume_ratio.has_value());
  EXPECT_GE(*result.volume_ratio, 1.0);
  EXPECT_LT(*result.volume_ratio, 1.0 + 1e-12);  // outward rounding adds ulps only
  EXPECT_GT(expect_pieces_contain_solid(slanted, result, 400), 80);
}

TEST(MeshDecomposition, ExactModeCoversATorusWithManyVerifiedPieces) {
  // 48 triangles, genus 1, the inner ring's edges reflex: CGAL 5.5 makes 34 pieces (many
  // slivers), all verified and rounded outward.
  const TriangleMesh ring = meshes::torus(6, 4, 3.0, 1.0);
  DecompositionOptions every_piece;
  every_piece.mode = DecomposeMode::kExact;
  every_piece.merge_volume_fraction = 0.0;
  const ConvexPieces all = decompose_mesh(ring, every_piece);
  EXPECT_EQ(all.pieces.size(), 34u);
  EXPECT_TRUE(all.warnings.empty());
  EXPECT_GE(*all.volume_ratio, 1.0);
  EXPECT_LT(*all.volume_ratio, 1.0 + 1e-12);
  EXPECT_GT(expect_pieces_contain_solid(ring, all, 300), 20);
  // Default: slivers merged for at most 0.1% more volume.
  const ConvexPieces result = decompose(ring, DecomposeMode::kExact);
  EXPECT_LT(result.pieces.size(), 34u);
  EXPECT_LE(*result.volume_ratio, 1.001 + 1e-12);
  EXPECT_GT(expect_pieces_contain_solid(ring, result, 300), 20);
  // One hull fills the hole: the exact pieces are far tighter.
  EXPECT_GT(*decompose(ring, DecomposeMode::kHull).volume_ratio, 1.5);
}

TEST(MeshDecomposition, ExactModeHandlesFinelyTriangulatedStlFaces) {
  // 448 triangles without shared vertices: every flat face is many coplanar triangles, all
  // of them coverers of the piece facets in their plane.
  const TriangleMesh fine = meshes::subdivided(meshes::u_fixture(), 2);
  ASSERT_EQ(fine.triangles.size(), 448u);
  const ConvexPieces result = decompose(fine, DecomposeMode::kExact);
  ASSERT_EQ(result.pieces.size(), 3u);
  EXPECT_EQ(sorted_volumes(result), (std::vector<double>{4.0, 4.0, 10.0}));
  EXPECT_EQ(*result.volume_ratio, 1.0);
  EXPECT_TRUE(result.warnings.empty());
}

TEST(MeshDecomposition, UnusedVerticesAreIgnoredWithAWarning) {
  TriangleMesh l = meshes::l_bracket();
  l.vertices.emplace_back(100, 100, 100);  // far outside: would blow up the hull if used
  ConvexPieces result = decompose(l, DecomposeMode::kHull);
  EXPECT_EQ(sorted_volumes(result), std::vector<double>{18.0});
  EXPECT_EQ(texts(result).front(), "1 vertex is used by no triangle and is ignored");
  l.vertices.emplace_back(-100, 0, 0);
  result = decompose(l, DecomposeMode::kParts);
  EXPECT_EQ(texts(result).front(), "2 vertices are used by no triangle and are ignored");
}

TEST(MeshDecomposition, ExactModeKeepsConvexComponentsWhole) {
  const TriangleMesh two = meshes::merged(meshes::l_bracket(), meshes::box({6, 0, 0}, {7, 1, 1}));
  const ConvexPieces result = decompose(two, DecomposeMode::kExact);
  ASSERT_EQ(result.pieces.size(), 3u);
  EXPECT_EQ(result.piece_origins[2], "component of triangle 20");
  EXPECT_EQ(*result.volume_ratio, 1.0);
  // STL-style input (no shared vertices) gives the same pieces.
  EXPECT_EQ(sorted_volumes(decompose(meshes::unshared(two), DecomposeMode::kExact)),
            sorted_volumes(result));
}

TEST(MeshDecomposition, OpenMeshIsCoveredByOneHullAndWarned) {
  TriangleMesh open = meshes::box({0, 0, 0}, {1, 1, 1}, "tray.stl");
  open.triangles.erase(open.triangles.begin() + 3);  // the y = 1 side
  open.triangles.erase(open.triangles.begin() + 1);
  for (const DecomposeMode mode : {DecomposeMode::kHull, DecomposeMode::kParts, DecomposeMode::kExact}) {
    const ConvexPieces result = decompose(open, mode);
    ASSERT_EQ(result.pieces.size(), 1u);
    EXPECT_EQ(result.pieces[0].size(), 8u);
    EXPECT_FALSE(result.volume_ratio.has_value());
    const std::vector<std::string> t = texts(result);
    ASSERT_EQ(t.size(), 1u);
    EXPECT_EQ(t[0].rfind("the mesh is not closed: 4 edges are used by an odd number of triangles "
                         "(first open edge: ",
                         0),
              0u)
        << t[0];
    EXPECT_NE(t[0].find("it bounds no solid"), std::string::npos);
    EXPECT_EQ(result.piece_origins[0], mode == DecomposeMode::kHull ? "all triangles" : "open triangles");
    for (const auto& v : open.vertices) EXPECT_TRUE(in_some_piece(result, v));
  }
}

TEST(MeshDecomposition, NamedClosedPartsAreSplitAndOpenPartsRegrouped) {
  // Two unit boxes sharing the face x = 1: one component, two closed named parts.
  TriangleMesh pair = meshes::merged(meshes::box({0, 0, 0}, {1, 1, 1}), meshes::box({1, 0, 0}, {2, 1, 1}));
  EXPECT_EQ(sorted_volumes(decompose(pair, DecomposeMode::kParts)), std::vector<double>{2.0});
  pair.part_names = {"left", "right"};
  pair.triangle_part.assign(24, 0);
  std::fill(pair.triangle_part.begin() + 12, pair.triangle_part.end(), 1);
  ConvexPieces result = decompose(pair, DecomposeMode::kParts);
  EXPECT_EQ(sorted_volumes(result), (std::vector<double>{1.0, 1.0}));
  EXPECT_EQ(result.piece_origins, (std::vector<std::string>{"part 'left', component of triangle 0",
                                                           "part 'right', component of triangle 12"}));
  // A tray and its lid as two open parts: regrouped into the one closed component.
  TriangleMesh boxed = meshes::box({0, 0, 0}, {1, 1, 1});
  boxed.part_names = {"tray", "lid"};
  boxed.triangle_part.assign(12, 0);
  boxed.triangle_part[1] = boxed.triangle_part[3] = 1;  // the y = 1 side
  result = decompose(boxed, DecomposeMode::kParts);
  EXPECT_EQ(sorted_volumes(result), std::vector<double>{1.0});
  EXPECT_EQ(result.piece_origins, std::vector<std::string>{"component of triangle 0"});
  EXPECT_TRUE(result.warnings.empty());
}

TEST(MeshDecomposition, FlatMeshIsAnErrorUnlessGivenAThickness) {
  TriangleMesh quad;
  quad.source = "plate.obj";
  quad.vertices = {{0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {0, 1, 0}};
  quad.triangles = {{0, 1, 2}, {0, 2, 3}};
  try {
    decompose(quad, DecomposeMode::kHull);
    ADD_FAILURE() << "a flat mesh was accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), "plate.obj");
    EXPECT_EQ(e.expected(), "a solid mesh, or a flat_thickness for a flat one");
    EXPECT_EQ(e.found(), "all 4 vertices of all triangles lie in one plane (a flat mesh bounds no solid)");
  }
  const ConvexPieces thick = decompose(quad, DecomposeMode::kHull, 0.25);
  ASSERT_EQ(thick.pieces.size(), 1u);
  EXPECT_EQ(sorted_volumes(thick), std::vector<double>{0.5});  // 2 x 1 x 0.25
  for (const auto& v : thick.pieces[0]) EXPECT_EQ(std::abs(v.z()), 0.125);
  EXPECT_EQ(texts(thick).back(),
            "all triangles: all 4 vertices lie in one plane; thickened by 0.25 along z "
            "(flat_thickness) into a solid that contains the mesh");
  // A tilted plate in x + y + z = 1 (exactly: dyadic coordinates): thickened along x (the
  // normal (1,1,1) ties; the first axis wins); the independent hull contains every vertex.
  TriangleMesh tilted;
  tilted.source = "tilted.obj";
  tilted.vertices = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0.25, 0.25, 0.5}};
  tilted.triangles = {{0, 1, 3}, {1, 2, 3}, {2, 0, 3}};
  // A power-of-two thickness keeps the shifted points exact, so the slab is a prism.
  const ConvexPieces slab = decompose(tilted, DecomposeMode::kParts, 0x1p-10);
  ASSERT_EQ(slab.pieces.size(), 1u);
  EXPECT_EQ(slab.pieces[0].size(), 6u);  // the triangle's corners, +- 2^-11 along x
  EXPECT_NE(texts(slab).back().find(" along x (flat_thickness)"), std::string::npos);
  for (const auto& v : tilted.vertices) EXPECT_TRUE(in_some_piece(slab, v));
  // Collinear: nothing to thicken.
  TriangleMesh line;
  line.source = "line.stl";
  line.vertices = {{0, 0, 0}, {1, 1, 1}, {2, 2, 2}};
  line.triangles = {{0, 1, 2}};
  EXPECT_THROW(decompose(line, DecomposeMode::kHull, 1.0), InputError);
}

TEST(MeshDecomposition, ExactModeFallsBackToTheHullWithTheReason) {
  // Two boxes sharing an edge: closed, but that edge bounds 4 triangles.
  const TriangleMesh edge_pair =
      meshes::merged(meshes::box({0, 0, 0}, {1, 1, 1}), meshes::box({1, 0, 1}, {2, 1, 2}));
  ConvexPieces result = decompose(edge_pair, DecomposeMode::kExact);
  ASSERT_EQ(result.pieces.size(), 1u);
  std::vector<std::string> t = texts(result);
  ASSERT_GE(t.size(), 1u);
  EXPECT_EQ(t[0].rfind("component of triangle 0: not decomposed exactly (edge ", 0), 0u) << t[0];
  EXPECT_NE(t[0].find("bounds 4 triangles); its convex hull is used"), std::string::npos) << t[0];

  // A box whose corner (1,1,1) is pulled through the face x = 0: closed, oriented, manifold,
  // but self-intersecting.
  TriangleMesh pierced = meshes::box({0, 0, 0}, {1, 1, 1});
  ASSERT_EQ(pierced.vertices[6], Eigen::Vector3d(1, 1, 1));
  pierced.vertices[6] = Eigen::Vector3d(-0.5, 0.5, 0.5);
  result = decompose(pierced, DecomposeMode::kExact);
  ASSERT_EQ(result.pieces.size(), 1u);
  t = texts(result);
  ASSERT_GE(t.size(), 1u);
  EXPECT_EQ(t[0], "component of triangle 0: not decomposed exactly (the surface intersects "
                  "itself); its convex hull is used");
}

TEST(MeshDecomposition, InvalidMeshesAndOptionsAreRejected) {
  TriangleMesh bad = meshes::l_bracket();
  bad.vertices[0].x() = std::nan("");
  EXPECT_THROW(decompose(bad, DecomposeMode::kParts), InputError);
  DecompositionOptions options;
  options.warn_volume_ratio = 0.5;
  EXPECT_THROW(decompose_mesh(meshes::l_bracket(), options), std::invalid_argument);
  EXPECT_THROW(decompose(meshes::l_bracket(), DecomposeMode::kHull, -1.0), std::invalid_argument);
}

TEST(MeshDecomposition, ModeNamesRoundTrip) {
  for (const DecomposeMode mode : {DecomposeMode::kHull, DecomposeMode::kParts, DecomposeMode::kExact}) {
    EXPECT_TRUE(parse_decompose_mode(decompose_mode_name(mode)) == mode);
  }
  EXPECT_EQ(decompose_mode_name(DecomposeMode::kParts), "parts");
  EXPECT_FALSE(parse_decompose_mode("convex").has_value());
  EXPECT_FALSE(parse_decompose_mode("Hull").has_value());
}

}  // namespace
}  // namespace grpvss::geometry

#include "grpvss/exact/mesh_validation.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "geometry/mesh_fixtures.hpp"
#include "grpvss/common/input_error.hpp"

namespace grpvss::geometry {
namespace {

namespace meshes = testing::meshes;

/// The InputError validate_mesh throws, or a failure.
InputError error_of(const TriangleMesh& mesh) {
  try {
    validate_mesh(mesh);
  } catch (const InputError& e) {
    return e;
  }
  ADD_FAILURE() << "validate_mesh accepted the mesh";
  return InputError("", 0, "");
}

TEST(MeshValidation, AcceptsTheFixtures) {
  EXPECT_NO_THROW(validate_mesh(meshes::l_bracket()));
  EXPECT_NO_THROW(validate_mesh(meshes::torus(8, 6, 2.0, 0.5)));
}

TEST(MeshValidation, NamesTheFileAndTheOffendingElement) {
  TriangleMesh mesh = meshes::l_bracket();
  mesh.vertices[5].y() = std::numeric_limits<double>::quiet_NaN();
  InputError e = error_of(mesh);
  EXPECT_EQ(e.file(), "l_bracket.stl");
  EXPECT_EQ(e.line(), 0);
  EXPECT_EQ(e.expected(), "finite vertex coordinates");
  EXPECT_EQ(e.found(), "vertex 5 at (0, nan, 3)");

  mesh = meshes::l_bracket();
  mesh.vertices[2].x() = -std::numeric_limits<double>::infinity();
  EXPECT_EQ(error_of(mesh).found(), "vertex 2 at (-inf, 0, 1)");

  mesh = meshes::l_bracket();
  mesh.vertices[7].z() = 2.5e6;  // millimetres read as metres, say
  e = error_of(mesh);
  EXPECT_EQ(e.expected(), "|coordinates| <= 1e6 model units (is the file's unit or scale right?)");
  EXPECT_EQ(e.found(), "vertex 7 at (4, 2, 2500000)");

  mesh = meshes::l_bracket();
  mesh.triangles[9][1] = 12;  // 12 vertices: 0..11
  e = error_of(mesh);
  EXPECT_EQ(e.expected(), "vertex indices 0..11");
  EXPECT_EQ(e.found(), "triangle 9 uses vertex 12");
  mesh.triangles[9][1] = -1;
  EXPECT_EQ(error_of(mesh).found(), "triangle 9 uses vertex -1");

  mesh = meshes::l_bracket();
  mesh.triangles.clear();
  e = error_of(mesh);
  EXPECT_EQ(e.expected(), "a mesh with at least one triangle");
  EXPECT_EQ(e.found(), "12 vertices and no triangles");

  mesh = meshes::l_bracket();
  mesh.part_names = {"a", "b"};
  mesh.triangle_part.assign(mesh.triangles.size(), 0);
  mesh.triangle_part[3] = 2;
  EXPECT_EQ(error_of(mesh).found(), "triangle 3 in part 2");
  mesh.triangle_part.pop_back();
  EXPECT_EQ(error_of(mesh).expected(), "a part for each of the 20 triangles");
}

TEST(MeshTopology, ClosedOrientedFixturesHaveNoBadEdges) {
  for (const TriangleMesh& mesh : {meshes::l_bracket(), meshes::u_fixture(), meshes::torus(8, 6, 2, 0.5)}) {
    const MeshTopology t = mesh_topology(mesh);
    EXPECT_TRUE(t.closed());
    EXPECT_TRUE(t.closed_and_oriented());
    EXPECT_EQ(t.degenerate_count, 0);
    EXPECT_EQ(t.unused_vertices, 0);
    EXPECT_EQ(t.welded_points.size(), mesh.vertices.size());
  }
}

TEST(MeshTopology, WeldsStlStyleVerticesBackIntoAClosedSurface) {
  const TriangleMesh soup = meshes::unshared(meshes::l_bracket());
  ASSERT_EQ(soup.vertices.size(), 60u);  // 20 triangles x 3
  const MeshTopology t = mesh_topology(soup);
  EXPECT_EQ(t.welded_points.size(), 12u);
  EXPECT_TRUE(t.closed_and_oriented());
  std::vector<int> all(soup.triangles.size());
  for (std::size_t i = 0; i < all.size(); ++i) all[i] = static_cast<int>(i);
  EXPECT_EQ(connected_triangle_groups(soup, t, all, false).size(), 1u);
}

TEST(MeshTopology, CountsOpenNonManifoldAndMisorientedEdges) {
  // A box without its y = 1 side (triangles 1 and 3 of the fixture): 4 open edges around
  // the square hole (the removed diagonal is no edge any more).
  TriangleMesh open = meshes::box({0, 0, 0}, {1, 1, 1});
  open.triangles.erase(open.triangles.begin() + 3);
  open.triangles.erase(open.triangles.begin() + 1);
  MeshTopology t = mesh_topology(open);
  EXPECT_FALSE(t.closed());
  EXPECT_EQ(t.open_edges, 4);
  EXPECT_EQ(t.odd_edges, 4);
  ASSERT_TRUE(t.first_open_edge.has_value());
  EXPECT_EQ(t.nonmanifold_edges, 0);

  // Two boxes sharing the edge x = 1, z = 1 (along y): that edge bounds 4 triangles.
  const TriangleMesh pair = meshes::merged(meshes::box({0, 0, 0}, {1, 1, 1}), meshes::box({1, 0, 1}, {2, 1, 2}));
  t = mesh_topology(pair);
  EXPECT_TRUE(t.closed());
  EXPECT_EQ(t.nonmanifold_edges, 1);
  EXPECT_FALSE(t.closed_and_oriented());

  // One triangle flipped: its 3 edges are used twice in one direction.
  TriangleMesh flipped = meshes::l_bracket();
  std::swap(flipped.triangles[4][1], flipped.triangles[4][2]);
  t = mesh_topology(flipped);
  EXPECT_TRUE(t.closed());
  EXPECT_EQ(t.misoriented_edges, 3);
  ASSERT_TRUE(t.first_misoriented_edge.has_value());
  EXPECT_LE(t.first_misoriented_edge->triangle, 4);  // the first triangle using such an edge
}

TEST(MeshTopology, MarksDegenerateTrianglesAndUnusedVertices) {
  TriangleMesh mesh = meshes::l_bracket();
  mesh.vertices.emplace_back(0.5, 0, 0);  // vertex 12, on the line through vertices 0 and 1
  mesh.vertices.emplace_back(9, 9, 9);    // unused
  mesh.triangles.push_back({0, 12, 1});   // collinear corners: zero area
  mesh.triangles.push_back({0, 0, 1});    // repeated corner
  const MeshTopology t = mesh_topology(mesh);
  EXPECT_EQ(t.degenerate_count, 2);
  EXPECT_TRUE(t.degenerate[20]);
  EXPECT_TRUE(t.degenerate[21]);
  EXPECT_FALSE(t.degenerate[19]);
  EXPECT_EQ(t.unused_vertices, 1);
}

TEST(MeshTopology, ExactModeProblemsNameTheElement) {
  const TriangleMesh l = meshes::l_bracket();
  std::vector<int> all(l.triangles.size());
  for (std::size_t i = 0; i < all.size(); ++i) all[i] = static_cast<int>(i);
  EXPECT_FALSE(oriented_manifold_problem(l, mesh_topology(l), all).has_value());

  TriangleMesh flipped = l;
  std::swap(flipped.triangles[4][1], flipped.triangles[4][2]);
  const auto problem = oriented_manifold_problem(flipped, mesh_topology(flipped), all);
  ASSERT_TRUE(problem.has_value());
  EXPECT_NE(problem->find("inconsistent orientation"), std::string::npos) << *problem;

  // Two boxes touching at one corner: closed, edge-manifold, pinched vertex.
  const TriangleMesh corner = meshes::merged(meshes::box({0, 0, 0}, {1, 1, 1}), meshes::box({1, 1, 1}, {2, 2, 2}));
  std::vector<int> both(corner.triangles.size());
  for (std::size_t i = 0; i < both.size(); ++i) both[i] = static_cast<int>(i);
  const MeshTopology ct = mesh_topology(corner);
  EXPECT_TRUE(ct.closed_and_oriented());
  EXPECT_EQ(connected_triangle_groups(corner, ct, both, false).size(), 1u);
  const auto pinched = oriented_manifold_problem(corner, ct, both);
  ASSERT_TRUE(pinched.has_value());
  EXPECT_NE(pinched->find("non-manifold vertex"), std::string::npos) << *pinched;
}

}  // namespace
}  // namespace grpvss::geometry

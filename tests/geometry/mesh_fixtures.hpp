#pragma once
/// \file
/// \brief Test meshes built in code (no files): an L-bracket and a U-fixture (extruded
/// non-convex polygons, closed and consistently oriented outward), boxes, an open box, a
/// torus, and helpers to merge meshes or unshare vertices as STL files do. Header-only so
/// that tests/bench can use them too.

#include <array>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "grpvss/model/triangle_mesh.hpp"

namespace grpvss::testing::meshes {

/// The polygon (x_i, z_i) — counter-clockwise in (x, z) — extruded along y over [0, depth],
/// caps triangulated by `cap` (counter-clockwise triples of polygon indices). Outward
/// orientation: the y = 0 cap faces -y, and e_x x e_z = -e_y, so counter-clockwise (x, z)
/// triangles are used as they are there and reversed at y = depth; each side quad
/// (i -> j along the polygon, interior on the left) is (f_i, b_j, f_j), (f_i, b_i, b_j).
inline TriangleMesh extruded(const std::vector<Eigen::Vector2d>& polygon,
                             const std::vector<std::array<int, 3>>& cap, double depth,
                             std::string source) {
  TriangleMesh mesh;
  mesh.source = std::move(source);
  const int n = static_cast<int>(polygon.size());
  for (const double y : {0.0, depth}) {
    for (const auto& p : polygon) mesh.vertices.emplace_back(p.x(), y, p.y());
  }
  for (const auto& t : cap) {
    mesh.triangles.push_back({t[0], t[1], t[2]});
    mesh.triangles.push_back({n + t[0], n + t[2], n + t[1]});
  }
  for (int i = 0; i < n; ++i) {
    const int j = (i + 1) % n;
    mesh.triangles.push_back({i, n + j, j});
    mesh.triangles.push_back({i, n + i, n + j});
  }
  return mesh;
}

/// L profile [0,4]x[0,1] u [0,1]x[0,3] (area 6) extruded by 2: volume 12; its convex hull
/// has profile (0,0) (4,0) (4,1) (1,3) (0,3), area 9: hull volume 18 (ratio 1.5).
inline TriangleMesh l_bracket() {
  return extruded({{0, 0}, {4, 0}, {4, 1}, {1, 1}, {1, 3}, {0, 3}},
                  {{0, 1, 2}, {0, 2, 3}, {0, 3, 4}, {0, 4, 5}}, 2.0, "l_bracket.stl");
}

/// U profile [0,5]x[0,1] u [0,1]x[0,3] u [4,5]x[0,3] (area 9) extruded by 2: volume 18; hull
/// [0,5]x[0,2]x[0,3]: volume 30 (ratio 5/3).
inline TriangleMesh u_fixture() {
  return extruded({{0, 0}, {5, 0}, {5, 3}, {4, 3}, {4, 1}, {1, 1}, {1, 3}, {0, 3}},
                  {{0, 1, 4}, {1, 2, 3}, {1, 3, 4}, {0, 4, 5}, {0, 5, 6}, {0, 6, 7}}, 2.0,
                  "u_fixture.stl");
}

/// The axis-aligned box [lo, hi] as 12 outward triangles on 8 shared vertices.
inline TriangleMesh box(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi,
                        std::string source = "box.stl") {
  TriangleMesh mesh = extruded({{lo.x(), lo.z()}, {hi.x(), lo.z()}, {hi.x(), hi.z()}, {lo.x(), hi.z()}},
                               {{0, 1, 2}, {0, 2, 3}}, 1.0, std::move(source));
  for (auto& v : mesh.vertices) v.y() = (v.y() == 0.0) ? lo.y() : hi.y();
  return mesh;
}

/// Both meshes in one (b's indices shifted), source of a.
inline TriangleMesh merged(const TriangleMesh& a, const TriangleMesh& b) {
  TriangleMesh mesh = a;
  const int shift = static_cast<int>(a.vertices.size());
  mesh.vertices.insert(mesh.vertices.end(), b.vertices.begin(), b.vertices.end());
  for (const auto& t : b.triangles) mesh.triangles.push_back({t[0] + shift, t[1] + shift, t[2] + shift});
  return mesh;
}

/// Every triangle with its own three vertices (as an STL file stores them).
inline TriangleMesh unshared(const TriangleMesh& shared) {
  TriangleMesh mesh;
  mesh.source = shared.source;
  for (const auto& t : shared.triangles) {
    const int base = static_cast<int>(mesh.vertices.size());
    for (int k = 0; k < 3; ++k) mesh.vertices.push_back(shared.vertices[t[k]]);
    mesh.triangles.push_back({base, base + 1, base + 2});
  }
  return mesh;
}

/// Each triangle split into 4 by its edge midpoints, `levels` times (4^levels as many
/// triangles, same surface). Triangles get their own vertices, as in an STL file; shared
/// midpoints are bit-identical ((p + q) / 2 either way), so welding joins them again.
inline TriangleMesh subdivided(const TriangleMesh& mesh, int levels) {
  TriangleMesh current = unshared(mesh);
  for (int level = 0; level < levels; ++level) {
    TriangleMesh next;
    next.source = current.source;
    for (const auto& t : current.triangles) {
      const Eigen::Vector3d a = current.vertices[t[0]], b = current.vertices[t[1]],
                            c = current.vertices[t[2]];
      const Eigen::Vector3d ab = (a + b) / 2, bc = (b + c) / 2, ca = (c + a) / 2;
      for (const auto& [p, q, r] : {std::array<Eigen::Vector3d, 3>{a, ab, ca}, {ab, b, bc},
                                    {ca, bc, c}, {ab, bc, ca}}) {
        const int base = static_cast<int>(next.vertices.size());
        next.vertices.insert(next.vertices.end(), {p, q, r});
        next.triangles.push_back({base, base + 1, base + 2});
      }
    }
    current = std::move(next);
  }
  return current;
}

/// Torus around z: `around` segments of the major circle (radius R), `across` of the tube
/// (radius r); 2 * around * across outward triangles. Vertices rounded doubles.
inline TriangleMesh torus(int around, int across, double R, double r) {
  TriangleMesh mesh;
  mesh.source = "torus.stl";
  const double pi = 3.14159265358979323846;
  for (int i = 0; i < around; ++i) {
    const double u = 2 * pi * i / around;
    for (int j = 0; j < across; ++j) {
      const double v = 2 * pi * j / across;
      mesh.vertices.emplace_back((R + r * std::cos(v)) * std::cos(u),
                                 (R + r * std::cos(v)) * std::sin(u), r * std::sin(v));
    }
  }
  const auto id = [&](int i, int j) { return (i % around) * across + (j % across); };
  for (int i = 0; i < around; ++i) {
    for (int j = 0; j < across; ++j) {
      mesh.triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      mesh.triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  }
  return mesh;
}

}  // namespace grpvss::testing::meshes

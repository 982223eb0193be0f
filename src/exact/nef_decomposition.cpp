/// \file
/// \brief CGAL translation unit of the `exact` mesh decomposition (keep every Nef polyhedron
/// include HERE: this file alone takes minutes and GBs to compile). Exact constructions
/// kernel throughout; the results are verified elsewhere (verify_exact_cover).

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Nef_polyhedron_3.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/convex_decomposition_3.h>
#include <CGAL/convex_hull_3.h>

#include <boost/multiprecision/gmp.hpp>

#include <stdexcept>
#include <type_traits>
#include <vector>

#include "grpvss/exact/nef_decomposition.hpp"

namespace grpvss::geometry {

namespace {

using Kernel = CGAL::Exact_predicates_exact_constructions_kernel;
using Point = Kernel::Point_3;
using Polyhedron = CGAL::Polyhedron_3<Kernel>;
using Nef = CGAL::Nef_polyhedron_3<Kernel>;
using HullMesh = CGAL::Surface_mesh<Point>;
namespace PMP = CGAL::Polygon_mesh_processing;

/// An exact rational as a GMP rational, whatever rational type CGAL was configured with
/// (a template, so that only the matching branch is compiled).
template <class Exact>
mpq_class exact_to_mpq(const Exact& exact) {
  if constexpr (std::is_same_v<Exact, mpq_class>) {
    return exact;
  } else if constexpr (std::is_same_v<Exact, CGAL::Gmpq>) {
    return mpq_class(exact.mpq());
  } else if constexpr (std::is_same_v<Exact, boost::multiprecision::mpq_rational>) {
    return mpq_class(exact.backend().data());
  } else {
    static_assert(std::is_same_v<Exact, mpq_class>, "unsupported CGAL exact rational type");
  }
}

mpq_class to_mpq(const Kernel::FT& value) { return exact_to_mpq(CGAL::exact(value)); }

Polyhedron to_polyhedron(const std::vector<Eigen::Vector3d>& vertices,
                         const std::vector<std::array<int, 3>>& triangles) {
  std::vector<Point> points;
  points.reserve(vertices.size());
  for (const auto& v : vertices) points.emplace_back(v.x(), v.y(), v.z());
  std::vector<std::array<std::size_t, 3>> faces;
  faces.reserve(triangles.size());
  for (const auto& t : triangles) {
    faces.push_back({static_cast<std::size_t>(t[0]), static_cast<std::size_t>(t[1]),
                     static_cast<std::size_t>(t[2])});
  }
  if (!PMP::is_polygon_soup_a_polygon_mesh(faces)) {
    throw std::invalid_argument("nef decomposition: the triangles do not form a manifold surface");
  }
  Polyhedron polyhedron;
  PMP::polygon_soup_to_polygon_mesh(points, faces, polyhedron);
  return polyhedron;
}

/// Exact convex hull of one decomposition volume's vertices, with its outward triangles.
RationalPiece hull_piece(const std::vector<Point>& points) {
  HullMesh hull;
  CGAL::convex_hull_3(points.begin(), points.end(), hull);
  RationalPiece piece;
  std::vector<int> slot(hull.number_of_vertices() + hull.number_of_removed_vertices(), -1);
  for (auto v : hull.vertices()) {
    slot[v.idx()] = static_cast<int>(piece.vertices.size());
    const Point& p = hull.point(v);
    piece.vertices.push_back({to_mpq(p.x()), to_mpq(p.y()), to_mpq(p.z())});
  }
  for (auto f : hull.faces()) {
    std::array<int, 3> triangle{};
    int k = 0;
    for (auto v : CGAL::vertices_around_face(hull.halfedge(f), hull)) {
      if (k == 3) throw std::logic_error("convex_hull_3 produced a non-triangle face");
      triangle[k++] = slot[v.idx()];
    }
    if (k != 3) throw std::logic_error("convex_hull_3 produced a non-triangle face");
    piece.triangles.push_back(triangle);
  }
  return piece;
}

}  // namespace

bool surface_self_intersects(const std::vector<Eigen::Vector3d>& vertices,
                             const std::vector<std::array<int, 3>>& triangles) {
  const Polyhedron polyhedron = to_polyhedron(vertices, triangles);
  return PMP::does_self_intersect(polyhedron);
}

std::vector<RationalPiece> nef_convex_decomposition(
    const std::vector<Eigen::Vector3d>& vertices,
    const std::vector<std::array<int, 3>>& triangles) {
  Polyhedron polyhedron = to_polyhedron(vertices, triangles);
  Nef nef(polyhedron);
  CGAL::convex_decomposition_3(nef);
  std::vector<RationalPiece> pieces;
  // The first volume is the unbounded outer one.
  for (auto volume = ++nef.volumes_begin(); volume != nef.volumes_end(); ++volume) {
    if (!volume->mark()) continue;
    Polyhedron shell;
    nef.convert_inner_shell_to_polyhedron(volume->shells_begin(), shell);
    std::vector<Point> points;
    for (auto v = shell.vertices_begin(); v != shell.vertices_end(); ++v) {
      points.push_back(v->point());
    }
    pieces.push_back(hull_piece(points));
  }
  return pieces;
}

}  // namespace grpvss::geometry

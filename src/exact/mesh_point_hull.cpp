/// \file
/// \brief Verified hulls of mesh vertex groups, with the flat-group fallback.

#include "grpvss/exact/mesh_point_hull.hpp"

#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "grpvss/common/input_error.hpp"
#include "grpvss/exact/points_in_polytope.hpp"
#include "grpvss/exact/rational_vector.hpp"
#include "grpvss/exact/shape_limits.hpp"

namespace grpvss::geometry {

namespace {

/// Exact affine dimension (0..3) of a non-empty point set; `normal` is a (rounded) normal
/// of the plane when the dimension is 2.
int affine_dimension(const std::vector<Eigen::Vector3d>& points, Eigen::Vector3d& normal) {
  const RationalVector p0 = to_rational(points.front());
  std::size_t i = 1;
  while (i < points.size() && points[i] == points.front()) ++i;
  if (i == points.size()) return 0;
  const RationalVector u = to_rational(points[i]) - p0;
  RationalVector n{0, 0, 0};
  std::size_t j = i + 1;
  for (; j < points.size(); ++j) {
    n = cross(u, to_rational(points[j]) - p0);
    if (sgn(n[0]) != 0 || sgn(n[1]) != 0 || sgn(n[2]) != 0) break;
  }
  if (j >= points.size()) return 1;
  for (std::size_t k = j + 1; k < points.size(); ++k) {
    if (sgn(dot(n, to_rational(points[k]) - p0)) != 0) return 3;
  }
  normal = Eigen::Vector3d(n[0].get_d(), n[1].get_d(), n[2].get_d());
  return 2;
}

/// p +- t/2 along axis k, rounded away from p_k (never onto it).
std::vector<Eigen::Vector3d> thickened(const std::vector<Eigen::Vector3d>& points, int axis,
                                       double thickness) {
  std::vector<Eigen::Vector3d> out;
  out.reserve(2 * points.size());
  const double inf = std::numeric_limits<double>::infinity();
  for (const auto& p : points) {
    Eigen::Vector3d up = p, down = p;
    up[axis] = p[axis] + thickness / 2;
    down[axis] = p[axis] - thickness / 2;
    if (!(up[axis] > p[axis])) up[axis] = std::nextafter(p[axis], inf);
    if (!(down[axis] < p[axis])) down[axis] = std::nextafter(p[axis], -inf);
    out.push_back(up);
    out.push_back(down);
  }
  return out;
}

std::string number_text(double x) {
  std::ostringstream out;
  out << x;
  return out.str();
}

}  // namespace

ConvexPolytope mesh_point_hull(const std::vector<Eigen::Vector3d>& points, double flat_thickness,
                               const std::string& source, const std::string& what,
                               std::vector<ShapeWarning>& warnings) {
  if (!std::isfinite(flat_thickness) || flat_thickness < 0 || flat_thickness > kMaxShapeCoordinate) {
    throw std::invalid_argument("flat_thickness must be finite and in [0, 1e6], got " +
                                number_text(flat_thickness));
  }
  if (points.empty()) throw std::invalid_argument("mesh_point_hull: no points");
  const std::string count = std::to_string(points.size());
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();
  const int dimension = affine_dimension(points, normal);
  if (dimension < 2) {
    throw InputError(source, 0, "a mesh whose vertices span 3-D",
                     "all " + count + " vertices of " + what +
                         (dimension == 0 ? " coincide" : " lie on one line"));
  }
  std::vector<Eigen::Vector3d> hull_points = points;
  if (dimension == 2) {
    if (flat_thickness == 0.0) {
      throw InputError(source, 0, "a solid mesh, or a flat_thickness for a flat one",
                       "all " + count + " vertices of " + what +
                           " lie in one plane (a flat mesh bounds no solid)");
    }
    int axis = 0;
    normal.cwiseAbs().maxCoeff(&axis);
    hull_points = thickened(points, axis, flat_thickness);
    warnings.push_back({source, 0,
                        what + ": all " + count + " vertices lie in one plane; thickened by " +
                            number_text(flat_thickness) + " along " + "xyz"[axis] +
                            " (flat_thickness) into a solid that contains the mesh"});
  }
  // proof: proofs/shape-containment.md#lemma-hull-cover (checked, not assumed)
  ConvexPolytope hull = ConvexPolytope::from_points(hull_points);
  if (!points_inside_exactly(hull, points)) {
    throw std::logic_error("mesh_point_hull: the exact hull does not contain its points");
  }
  return hull;
}

}  // namespace grpvss::geometry

#include "grpvss/geometry/centroid_cull.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "grpvss/geometry/directed_rounding.hpp"

namespace grpvss::geometry {
namespace {

Eigen::Vector3d vertex_mean(const std::vector<Eigen::Vector3d>& points) {
  if (points.empty()) throw std::invalid_argument("centroid sphere of an empty point set");
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (const auto& p : points) sum += p;
  return sum / static_cast<double>(points.size());
}

}  // namespace

CentroidSphere thesis_centroid_sphere(const std::vector<Eigen::Vector3d>& points) {
  CentroidSphere sphere;
  sphere.centroid = vertex_mean(points);  // Eq. 4-19
  for (const auto& p : points) {           // Eq. 4-20
    sphere.radius = std::max(sphere.radius, (sphere.centroid - p).norm());
  }
  return sphere;
}

ThesisCullRecord thesis_prejudge(const CentroidSphere& i, const CentroidSphere& j,
                                 double tolerance) {
  ThesisCullRecord record;
  record.sphere_i = i;
  record.sphere_j = j;
  record.tolerance = tolerance;
  record.centroid_distance = (i.centroid - j.centroid).norm();                   // Eq. 4-21
  record.culled = record.centroid_distance >= i.radius + j.radius + tolerance;  // Eq. 4-22
  return record;
}

CertifiedSphere certified_sphere(const std::vector<Eigen::Vector3d>& points) {
  using namespace rounding;
  CertifiedSphere sphere;
  // The centre need not be the exact mean: the radius is proven for whatever double centre
  // we pick. proof: proofs/fast-path.md#centroid-sphere-cull
  sphere.center = vertex_mean(points);
  const UpwardRoundingScope upward;
  double radius2 = 0.0;
  for (const auto& p : points) {
    double d2 = 0.0;
    for (int k = 0; k < 3; ++k) {
      const double lo = sub_down(p[k], sphere.center[k]);
      const double hi = sub_up(p[k], sphere.center[k]);
      d2 = add_up(d2, square_up_of_range(lo, hi));
    }
    radius2 = std::max(radius2, d2);
  }
  sphere.radius_upper = sqrt_up(radius2);
  return sphere;
}

CertifiedCullRecord certified_sphere_cull(const CertifiedSphere& i, const CertifiedSphere& j,
                                          double required_gap) {
  using namespace rounding;
  CertifiedCullRecord record;
  record.sphere_i = i;
  record.sphere_j = j;
  record.required_gap = required_gap;
  const UpwardRoundingScope upward;
  double d2 = 0.0;
  for (int k = 0; k < 3; ++k) {
    const double lo = sub_down(i.center[k], j.center[k]);
    const double hi = sub_up(i.center[k], j.center[k]);
    d2 = add_down(d2, square_down_of_range(lo, hi));
  }
  record.center_distance_lower = sqrt_down(d2);
  record.sphere_gap_lower =
      sub_down(sub_down(record.center_distance_lower, i.radius_upper), j.radius_upper);
  record.culled = record.sphere_gap_lower >= required_gap && record.sphere_gap_lower > 0.0;
  return record;
}

}  // namespace grpvss::geometry

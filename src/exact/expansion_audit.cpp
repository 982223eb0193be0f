// Measures tolerance expansions against the exact ball-sum containment test.
#include "grpvss/exact/expansion_audit.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <Eigen/Geometry>

#include "grpvss/exact/minkowski_offset.hpp"
#include "grpvss/geometry/thesis_expansion.hpp"

namespace grpvss::geometry {
namespace {

constexpr double kPi = 3.14159265358979323846;

double face_area(const ConvexPolytope& p, int face) {
  const auto& loop = p.faces()[face];
  Eigen::Vector3d twice_area = Eigen::Vector3d::Zero();
  for (std::size_t i = 0; i < loop.size(); ++i) {
    twice_area += p.vertices()[loop[i]].cross(p.vertices()[loop[(i + 1) % loop.size()]]);
  }
  return 0.5 * std::abs(p.face_normals()[face].dot(twice_area));
}

/// Fills the containment, size and inflation columns for an expansion given by its points.
ExpansionMeasure measure(ExpansionMethod method, const ConvexPolytope& expansion,
                         const std::vector<Eigen::Vector3d>& hull_points, double tolerance,
                         double ideal_volume) {
  ExpansionMeasure m;
  m.method = method;
  const BallSumContainmentReport report =
      ball_sum_containment_report(expansion, hull_points, tolerance);
  m.contains_ball_sum = report.contained;
  m.worst_protrusion = report.worst_protrusion;
  m.worst_point = report.worst_point;
  m.vertex_count = static_cast<int>(expansion.vertices().size());
  m.volume = expansion.volume();
  m.over_inflation = m.volume / ideal_volume;
  return m;
}

template <typename Scalar>
ExpansionMeasure measure_thesis(ExpansionMethod method, const HullPoints& hull, double tolerance,
                                double ideal_volume) {
  if (static_cast<int>(hull.points.size()) != kThesisPrismVertexCount) {
    ExpansionMeasure m;
    m.method = method;
    m.applicable = false;
    return m;
  }
  const ThesisExpansion<Scalar> thesis = expand_prism_as_thesis<Scalar>(hull, tolerance);
  std::vector<Eigen::Vector3d> points;
  for (const auto& v : thesis.vertices) points.push_back(v.template cast<double>());  // exact
  ExpansionMeasure m = measure(method, ConvexPolytope::from_points(points), hull.points,
                               tolerance, ideal_volume);
  m.max_midpoint_gap = static_cast<double>(thesis.max_midpoint_gap);
  m.parallel_pairs = static_cast<int>(
      std::count(thesis.parallel_lines.begin(), thesis.parallel_lines.end(), true));
  m.origin_on_cap_plane = thesis.origin_on_cap_plane;
  return m;
}

}  // namespace

double ball_sum_volume(const ConvexPolytope& hull, double radius) {
  double area = 0.0;
  for (int f = 0; f < static_cast<int>(hull.faces().size()); ++f) area += face_area(hull, f);
  double edge_term = 0.0;  // sum of length * exterior angle
  for (std::size_t e = 0; e < hull.edges().size(); ++e) {
    const auto& [u, v] = hull.edges()[e];
    const auto& [f0, f1] = hull.edge_faces()[e];
    const double cosine =
        std::clamp(hull.face_normals()[f0].dot(hull.face_normals()[f1]), -1.0, 1.0);
    edge_term += (hull.vertices()[u] - hull.vertices()[v]).norm() * std::acos(cosine);
  }
  return hull.volume() + area * radius + 0.5 * edge_term * radius * radius +
         4.0 / 3.0 * kPi * radius * radius * radius;
}

const char* to_string(ExpansionMethod method) {
  switch (method) {
    case ExpansionMethod::kThesisSingle: return "thesis-single";
    case ExpansionMethod::kThesisDouble: return "thesis-double";
    case ExpansionMethod::kCube: return "cube";
    case ExpansionMethod::kRhombicuboctahedron: return "rhombicuboctahedron";
  }
  throw std::logic_error("unknown ExpansionMethod");
}

ExpansionAudit audit_expansions(const RobotModel& robot, double tolerance) {
  if (!(tolerance > 0.0) || !std::isfinite(tolerance)) {
    throw std::invalid_argument("expansion audit needs a finite positive tolerance");
  }
  ExpansionAudit audit;
  audit.tolerance = tolerance;
  for (int link = 0; link < static_cast<int>(robot.links.size()); ++link) {
    const auto& hulls = robot.links[link].hulls;
    for (int h = 0; h < static_cast<int>(hulls.size()); ++h) {
      const HullPoints& points = hulls[h];
      const ConvexPolytope hull = ConvexPolytope::from_points(points.points);
      HullExpansionAudit row;
      row.link = link;
      row.hull = h;
      row.source_line = points.source_line;
      row.point_count = static_cast<int>(points.points.size());
      row.vertex_count = static_cast<int>(hull.vertices().size());
      row.volume = hull.volume();
      row.ball_sum_volume = ball_sum_volume(hull, tolerance);
      row.expansions.push_back(measure_thesis<float>(ExpansionMethod::kThesisSingle, points,
                                                     tolerance, row.ball_sum_volume));
      row.expansions.push_back(measure_thesis<double>(ExpansionMethod::kThesisDouble, points,
                                                      tolerance, row.ball_sum_volume));
      for (const auto& [method, shape] :
           {std::pair{ExpansionMethod::kCube, OffsetShape::kCube},
            std::pair{ExpansionMethod::kRhombicuboctahedron, OffsetShape::kRhombicuboctahedron}}) {
        row.expansions.push_back(measure(method, minkowski_offset(hull, tolerance, shape),
                                         points.points, tolerance, row.ball_sum_volume));
      }
      audit.hulls.push_back(std::move(row));
    }
  }
  return audit;
}

}  // namespace grpvss::geometry

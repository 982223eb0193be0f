/// \file
/// \brief Box, cylinder and sphere polytopes, each accepted only after the exact
/// support-function check (proofs/shape-containment.md#lemma-support-function). Floating point
/// proposes the vertices; the rational check decides.

#include "grpvss/exact/circumscribed_shapes.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>

#include <Eigen/Geometry>

#include "grpvss/exact/convex_polytope.hpp"
#include "grpvss/exact/shape_containment.hpp"

namespace grpvss::geometry {

namespace {

constexpr double kPi = 3.14159265358979323846;
/// Candidate inflations 2^(k - 45), k = 0..kAttempts-1: the first is ample for the rounding
/// of cos/sin/normalize; the rest are a safety net (the exact check decides).
constexpr int kAttempts = 8;
/// Relative margin kept between the polygon's overshoot and the requested maximum, so the
/// outward inflation never pushes the overshoot past it.
constexpr double kOvershootMargin = 1e-6;

void require_dimension(double value, const std::string& what) {
  if (!std::isfinite(value) || value <= 0.0 || value > kMaxShapeCoordinate) {
    throw std::invalid_argument(what + " must be finite, > 0 and <= 1e6 model units, got " +
                                std::to_string(value));
  }
}

void require_overshoot(double overshoot) {
  if (!(overshoot >= kMinRelativeOvershoot && overshoot <= kMaxRelativeOvershoot)) {
    throw std::invalid_argument("maximum relative overshoot must be in [0.001, 1], got " +
                                std::to_string(overshoot));
  }
}

double inflation(int attempt) { return 1.0 + std::ldexp(1.0, attempt - 45); }

/// Regular n-gon (n a multiple of 4), vertex angles (2i+1) pi / n, circumradius R: the first
/// octant is computed, the rest mirrored, so the polygon is exactly symmetric.
std::vector<Eigen::Vector2d> regular_polygon(int n, double circumradius) {
  const int quarter = n / 4;
  std::vector<Eigen::Vector2d> first_quadrant(quarter);
  for (int i = 0; 2 * i < quarter; ++i) {
    const double angle = (2 * i + 1) * kPi / n;
    const Eigen::Vector2d p(circumradius * std::cos(angle), circumradius * std::sin(angle));
    first_quadrant[i] = p;
    first_quadrant[quarter - 1 - i] = Eigen::Vector2d(p.y(), p.x());  // angle pi/2 - angle
  }
  std::vector<Eigen::Vector2d> polygon;
  for (const double sx : {1.0, -1.0}) {
    for (const double sy : {1.0, -1.0}) {
      for (const auto& p : first_quadrant) polygon.emplace_back(sx * p.x(), sy * p.y());
    }
  }
  return polygon;
}

// ---- geodesic icosphere -------------------------------------------------------------------

struct Geodesic {
  std::vector<Eigen::Vector3d> points;  // on the unit sphere (rounded)
  std::vector<std::array<int, 3>> triangles;
};

std::vector<Eigen::Vector3d> icosahedron_vertices() {
  const double phi = (1.0 + std::sqrt(5.0)) / 2.0;
  std::vector<Eigen::Vector3d> v;
  for (const double a : {-1.0, 1.0}) {
    for (const double b : {-phi, phi}) {
      v.emplace_back(0.0, a, b);
      v.emplace_back(a, b, 0.0);
      v.emplace_back(b, 0.0, a);
    }
  }
  return v;
}

/// The 20 faces: vertex triples at mutual distance 2.
std::vector<std::array<int, 3>> icosahedron_faces(const std::vector<Eigen::Vector3d>& v) {
  const auto adjacent = [&v](int i, int j) { return std::abs((v[i] - v[j]).squaredNorm() - 4.0) < 1e-9; };
  std::vector<std::array<int, 3>> faces;
  for (int i = 0; i < 12; ++i) {
    for (int j = i + 1; j < 12; ++j) {
      for (int k = j + 1; k < 12; ++k) {
        if (adjacent(i, j) && adjacent(j, k) && adjacent(i, k)) faces.push_back({i, j, k});
      }
    }
  }
  return faces;
}

/// Each icosahedron face split into nu^2 triangles, the grid points projected onto the unit
/// sphere. A point shared by faces is computed once (keyed by its icosahedron vertices and
/// weights), so shared points are bit-identical.
Geodesic geodesic_sphere(int nu) {
  const std::vector<Eigen::Vector3d> ico = icosahedron_vertices();
  Geodesic g;
  std::map<std::vector<std::pair<int, int>>, int> index_of;
  const auto point = [&](const std::array<int, 3>& face, int i, int j) {
    std::vector<std::pair<int, int>> key;
    for (const auto& [vertex, weight] : {std::pair{face[0], i}, {face[1], j}, {face[2], nu - i - j}}) {
      if (weight > 0) key.emplace_back(vertex, weight);
    }
    std::sort(key.begin(), key.end());
    const auto [it, inserted] = index_of.emplace(key, static_cast<int>(g.points.size()));
    if (inserted) {
      Eigen::Vector3d p = Eigen::Vector3d::Zero();
      for (const auto& [vertex, weight] : key) p += weight * ico[vertex];
      g.points.push_back(p.normalized());
    }
    return it->second;
  };
  for (const auto& face : icosahedron_faces(ico)) {
    for (int i = 0; i < nu; ++i) {
      for (int j = 0; i + j < nu; ++j) {
        g.triangles.push_back({point(face, i, j), point(face, i + 1, j), point(face, i, j + 1)});
        if (i + j + 1 < nu) {
          g.triangles.push_back(
              {point(face, i + 1, j), point(face, i + 1, j + 1), point(face, i, j + 1)});
        }
      }
    }
  }
  return g;
}

/// Smallest distance from the centre to a triangle plane of the geodesic sphere (double).
double smallest_plane_distance(const Geodesic& g) {
  double smallest = std::numeric_limits<double>::infinity();
  for (const auto& t : g.triangles) {
    const Eigen::Vector3d& a = g.points[t[0]];
    const Eigen::Vector3d n = (g.points[t[1]] - a).cross(g.points[t[2]] - a).normalized();
    smallest = std::min(smallest, std::abs(n.dot(a)));
  }
  return smallest;
}

/// The frequency-nu unit sphere with its hull's nearest face plane distance (the display
/// offsets of unit normals, to ~1e-16) and its triangles' smallest plane distance: both
/// depend on nu alone.
struct UnitGeodesic {
  Geodesic sphere;
  double nearest_face_offset = 0.0;
  double smallest_triangle_distance = 0.0;
};

/// The unit sphere of frequency nu, built once per process (a robot of capsules and a cell of
/// spheres ask for the same few). Only proposals come from it: every scaled sphere is checked
/// exactly.
const UnitGeodesic& unit_geodesic(int nu) {
  static std::mutex mutex;
  static std::map<int, std::unique_ptr<const UnitGeodesic>> built;
  const std::lock_guard<std::mutex> lock(mutex);
  std::unique_ptr<const UnitGeodesic>& slot = built[nu];
  if (!slot) {
    auto unit = std::make_unique<UnitGeodesic>();
    unit->sphere = geodesic_sphere(nu);
    const ConvexPolytope unit_hull = ConvexPolytope::from_points(unit->sphere.points);
    const std::vector<double>& offsets = unit_hull.face_offsets();
    unit->nearest_face_offset = *std::min_element(offsets.begin(), offsets.end());
    unit->smallest_triangle_distance = smallest_plane_distance(unit->sphere);
    slot = std::move(unit);
  }
  return *slot;
}

/// The frequency-nu sphere scaled so that its hull's face planes lie at distance >= radius,
/// if a candidate passes the exact checks (containment and overshoot).
std::optional<std::vector<Eigen::Vector3d>> scaled_geodesic_sphere(int nu, double radius,
                                                                   double max_overshoot) {
  const Geodesic& unit = unit_geodesic(nu).sphere;
  const double nearest = unit_geodesic(nu).nearest_face_offset;
  for (int attempt = 0; attempt < kAttempts; ++attempt) {
    const double scale = radius / nearest * inflation(attempt);
    std::vector<Eigen::Vector3d> points;
    points.reserve(unit.points.size());
    for (const auto& u : unit.points) points.push_back(scale * u);
    // proof: proofs/shape-containment.md#lemma-support-function
    const ConvexPolytope sphere = ConvexPolytope::from_points(points);
    if (!spherical_overshoot_at_most(sphere.vertices(), radius, max_overshoot)) break;
    if (sphere_inside_exactly(sphere, radius)) return sphere.vertices();
  }
  return std::nullopt;
}

/// Results of a pure shape function by its arguments, kept for the process (a robot of
/// capsules repeats a few radii; a cell repeats its posts). At most kMaxEntries are kept: a
/// long-lived process (batch, the Python module) meeting endless new sizes stops adding.
template <class Key>
class ShapeMemo {
 public:
  template <class Build>
  std::vector<Eigen::Vector3d> get(const Key& key, Build build) {
    {
      const std::lock_guard<std::mutex> lock(mutex_);
      const auto found = built_.find(key);
      if (found != built_.end()) return found->second;
    }
    std::vector<Eigen::Vector3d> points = build();  // outside the lock: it may take milliseconds
    const std::lock_guard<std::mutex> lock(mutex_);
    if (built_.size() < kMaxEntries) built_.emplace(key, points);
    return points;
  }

 private:
  static constexpr std::size_t kMaxEntries = 4096;
  std::mutex mutex_;
  std::map<Key, std::vector<Eigen::Vector3d>> built_;
};

}  // namespace

std::vector<Eigen::Vector3d> circumscribed_box(const Eigen::Vector3d& size) {
  for (int i = 0; i < 3; ++i) require_dimension(size[i], "box size");
  const Eigen::Vector3d half = size / 2.0;  // exact: halving a normal double
  std::vector<Eigen::Vector3d> corners;
  for (int i = 0; i < 8; ++i) {
    corners.emplace_back((i & 1) ? half.x() : -half.x(), (i & 2) ? half.y() : -half.y(),
                         (i & 4) ? half.z() : -half.z());
  }
  // proof: proofs/shape-containment.md#lemma-support-function (checked, not assumed)
  const ConvexPolytope box = ConvexPolytope::from_points(corners);
  if (!box_inside_exactly(box, size)) throw std::logic_error("box corners do not contain the box");
  return box.vertices();
}

int cylinder_polygon_sides(double max_relative_overshoot) {
  require_overshoot(max_relative_overshoot);
  int n = 4;
  while (1.0 / std::cos(kPi / n) - 1.0 > max_relative_overshoot * (1.0 - kOvershootMargin)) n += 4;
  return n;
}

std::vector<Eigen::Vector3d> circumscribed_cylinder(double radius, double length,
                                                    double max_relative_overshoot) {
  require_dimension(radius, "cylinder radius");
  require_dimension(length, "cylinder length");
  require_overshoot(max_relative_overshoot);  // before the lookup: a NaN key would match anything
  static ShapeMemo<std::array<double, 3>> memo;
  return memo.get({radius, length, max_relative_overshoot}, [&] {
    return build_circumscribed_cylinder(radius, length, max_relative_overshoot);
  });
}

std::vector<Eigen::Vector3d> build_circumscribed_cylinder(double radius, double length,
                                                          double max_relative_overshoot) {
  require_dimension(radius, "cylinder radius");
  require_dimension(length, "cylinder length");
  const int n = cylinder_polygon_sides(max_relative_overshoot);
  const double half = length / 2.0;
  for (int attempt = 0; attempt < kAttempts; ++attempt) {
    const double circumradius = radius / std::cos(kPi / n) * inflation(attempt);
    std::vector<Eigen::Vector3d> points;
    for (const auto& p : regular_polygon(n, circumradius)) {
      points.emplace_back(p.x(), p.y(), -half);
      points.emplace_back(p.x(), p.y(), half);
    }
    // proof: proofs/shape-containment.md#lemma-support-function
    const ConvexPolytope prism = ConvexPolytope::from_points(points);
    if (cylinder_inside_exactly(prism, radius, length) &&
        radial_overshoot_at_most(prism.vertices(), radius, max_relative_overshoot)) {
      return prism.vertices();
    }
  }
  throw std::logic_error("circumscribed_cylinder: no candidate passed the exact check");
}

int sphere_subdivision_frequency(double max_relative_overshoot) {
  require_overshoot(max_relative_overshoot);
  int nu = 1;
  while (1.0 / unit_geodesic(nu).smallest_triangle_distance - 1.0 >
         max_relative_overshoot * (1.0 - kOvershootMargin)) {
    ++nu;
  }
  return nu;
}

std::vector<Eigen::Vector3d> circumscribed_sphere(double radius, double max_relative_overshoot) {
  require_dimension(radius, "sphere radius");
  require_overshoot(max_relative_overshoot);
  static ShapeMemo<std::array<double, 2>> memo;
  return memo.get({radius, max_relative_overshoot},
                  [&] { return build_circumscribed_sphere(radius, max_relative_overshoot); });
}

std::vector<Eigen::Vector3d> build_circumscribed_sphere(double radius, double max_relative_overshoot) {
  require_dimension(radius, "sphere radius");
  const int first = sphere_subdivision_frequency(max_relative_overshoot);
  // The hull's faces are normally the subdivision triangles; if not, a finer sphere is tried.
  for (int nu = first; nu < first + 3; ++nu) {
    if (auto points = scaled_geodesic_sphere(nu, radius, max_relative_overshoot)) return *points;
  }
  throw std::logic_error("circumscribed_sphere: no candidate passed the exact check");
}

}  // namespace grpvss::geometry

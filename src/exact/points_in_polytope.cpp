/// \file
/// \brief Filtered exact point-in-polytope test for the verified mesh hulls
/// (proofs/shape-containment.md#lemma-hull-cover, implementation).

#include "grpvss/exact/points_in_polytope.hpp"

#include <cmath>

#include "grpvss/exact/rational_vector.hpp"

namespace grpvss::geometry {

namespace {

/// Sign of det[q - p, r - p, s - p] (positive: s on the side (q - p) x (r - p) points to):
/// Shewchuk's orient3d with error bound A (which covers the rounding of the differences),
/// exact rationals when the bound cannot decide or the permanent is tiny (underflow).
int orientation(const Eigen::Vector3d& p, const Eigen::Vector3d& q, const Eigen::Vector3d& r,
                const Eigen::Vector3d& s) {
  const double adx = q.x() - p.x(), ady = q.y() - p.y(), adz = q.z() - p.z();
  const double bdx = r.x() - p.x(), bdy = r.y() - p.y(), bdz = r.z() - p.z();
  const double cdx = s.x() - p.x(), cdy = s.y() - p.y(), cdz = s.z() - p.z();
  const double bdxcdy = bdx * cdy, cdxbdy = cdx * bdy;
  const double cdxady = cdx * ady, adxcdy = adx * cdy;
  const double adxbdy = adx * bdy, bdxady = bdx * ady;
  const double det = adz * (bdxcdy - cdxbdy) + bdz * (cdxady - adxcdy) + cdz * (adxbdy - bdxady);
  const double permanent = (std::abs(bdxcdy) + std::abs(cdxbdy)) * std::abs(adz) +
                           (std::abs(cdxady) + std::abs(adxcdy)) * std::abs(bdz) +
                           (std::abs(adxbdy) + std::abs(bdxady)) * std::abs(cdz);
  constexpr double kEpsilon = 0x1p-53;
  constexpr double kErrorBoundA = (7.0 + 56.0 * kEpsilon) * kEpsilon;
  if (std::isfinite(permanent) && permanent > 0x1p-900) {
    const double bound = kErrorBoundA * permanent;
    if (det > bound) return 1;
    if (-det > bound) return -1;
  }
  const RationalVector rp = to_rational(p);
  return sgn(dot(cross(to_rational(q) - rp, to_rational(r) - rp), to_rational(s) - rp));
}

}  // namespace

bool points_inside_exactly(const ConvexPolytope& p, const std::vector<Eigen::Vector3d>& points) {
  // vertex_of_input[i]: the polytope vertex that is points[i] (when p was built from points).
  std::vector<int> vertex_of_input(points.size(), -1);
  for (std::size_t v = 0; v < p.input_indices().size(); ++v) {
    const auto i = static_cast<std::size_t>(p.input_indices()[v]);
    if (i < points.size() && points[i] == p.vertices()[v]) vertex_of_input[i] = static_cast<int>(v);
  }
  std::vector<char> on_face(p.vertices().size(), 0);
  for (const auto& loop : p.faces()) {
    for (int v : loop) on_face[static_cast<std::size_t>(v)] = 1;
    const auto& a = p.vertices()[loop[0]];
    const auto& b = p.vertices()[loop[1]];
    const auto& c = p.vertices()[loop[2]];
    for (std::size_t i = 0; i < points.size(); ++i) {
      const int v = vertex_of_input[i];
      if (v >= 0 && on_face[static_cast<std::size_t>(v)]) continue;  // exactly on the plane
      if (orientation(a, b, c, points[i]) > 0) return false;
    }
    for (int v : loop) on_face[static_cast<std::size_t>(v)] = 0;
  }
  return true;
}

}  // namespace grpvss::geometry

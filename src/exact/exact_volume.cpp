/// \file
/// \brief Exact polytope and surface volumes in GMP rationals.

#include "grpvss/exact/exact_volume.hpp"

#include "grpvss/exact/rational_vector.hpp"

namespace grpvss::geometry {

namespace {

mpq_class triple(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  return dot(to_rational(a), cross(to_rational(b), to_rational(c)));
}

}  // namespace

mpq_class six_volume(const ConvexPolytope& p) {
  mpq_class sum = 0;
  const auto& v = p.vertices();
  for (const auto& loop : p.faces()) {
    for (std::size_t i = 1; i + 1 < loop.size(); ++i) {
      sum += triple(v[loop[0]], v[loop[i]], v[loop[i + 1]]);
    }
  }
  return sum;
}

mpq_class six_signed_volume(const std::vector<Eigen::Vector3d>& vertices,
                            const std::vector<std::array<int, 3>>& triangles) {
  mpq_class sum = 0;
  for (const auto& t : triangles) sum += triple(vertices[t[0]], vertices[t[1]], vertices[t[2]]);
  return sum;
}

}  // namespace grpvss::geometry

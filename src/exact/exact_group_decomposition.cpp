/// \file
/// \brief One closed group through the exact decomposition, verified before use.

#include "grpvss/exact/exact_group_decomposition.hpp"

#include <exception>
#include <string>
#include <utility>

#include "grpvss/exact/exact_cover_check.hpp"
#include "grpvss/exact/exact_volume.hpp"
#include "grpvss/exact/nef_decomposition.hpp"
#include "grpvss/exact/piece_merging.hpp"

namespace grpvss::geometry {

ExactGroupPieces exact_group_pieces(const std::vector<Eigen::Vector3d>& vertices,
                                    std::vector<std::array<int, 3>> triangles,
                                    const ConvexPolytope& hull, double merge_volume_fraction) {
  ExactGroupPieces result;
  const mpq_class six = six_signed_volume(vertices, triangles);
  if (sgn(six) == 0) {
    result.fallback_reason = "the surface encloses no volume";
    return result;
  }
  if (sgn(six) < 0) {  // inward: the Nef construction and the check want outward triangles
    for (auto& t : triangles) std::swap(t[1], t[2]);
  }
  // Hull volume = solid volume and solid inside the hull: the solid is its hull.
  if (six_volume(hull) == abs(six)) {
    result.pieces.push_back(hull);
    result.convex = true;
    return result;
  }
  if (surface_self_intersects(vertices, triangles)) {
    result.fallback_reason = "the surface intersects itself";
    return result;
  }
  std::vector<RationalPiece> exact;
  try {
    exact = nef_convex_decomposition(vertices, triangles);
  } catch (const std::exception& e) {  // a CGAL precondition or assertion: the hull is sound
    result.fallback_reason = std::string("the exact decomposition failed: ") + e.what();
    return result;
  }
  // proof: proofs/shape-containment.md#lemma-exact-cover (the decomposition is not trusted)
  const ExactCoverCheck check = verify_exact_cover(exact, vertices, triangles);
  if (!check.covered) {
    result.fallback_reason = "the exact pieces failed verification: " + check.failure;
    return result;
  }
  std::vector<ConvexPolytope> rounded;
  for (const RationalPiece& piece : exact) {
    // proof: proofs/shape-containment.md#lemma-outward-rounding
    rounded.push_back(ConvexPolytope::from_points(enclosing_double_points(piece)));
  }
  if (merge_volume_fraction > 0.0) {
    const double solid_volume = mpq_class(abs(six)).get_d() / 6.0;
    rounded = merge_pieces(std::move(rounded), merge_volume_fraction * solid_volume);
  }
  result.pieces = std::move(rounded);
  return result;
}

}  // namespace grpvss::geometry

#pragma once
/// \file
/// \brief A convex piece with EXACT rational vertices and its claimed boundary, as the exact
/// convex decomposition produces it (before its vertices are rounded outward to doubles).
///
/// Nothing about a RationalPiece is trusted: verify_exact_cover() checks the boundary claims
/// and the covering, in exact arithmetic (proofs/shape-containment.md#lemma-exact-cover).

#include <array>
#include <vector>

#include <gmpxx.h>

namespace grpvss::geometry {

/// \brief A point with exact rational coordinates.
struct RationalPoint {
  mpq_class x, y, z;
};

/// \brief The piece conv(vertices) and its outward boundary triangles (indices into vertices),
/// counter-clockwise seen from outside.
struct RationalPiece {
  std::vector<RationalPoint> vertices;
  std::vector<std::array<int, 3>> triangles;
};

}  // namespace grpvss::geometry

#pragma once
/// \file
/// \brief The polytope family of the tolerance expansion (proofs/tolerance-offset.md).

#include <optional>
#include <string_view>

namespace grpvss::geometry {

/// \brief Which polytope circumscribes the ball B(0, r).
enum class OffsetShape {
  /// Cube of half-side r: what the thesis's \f$\sqrt{2}\Delta\f$ edge offset amounts to.
  /// Circumradius \f$\sqrt{3}\,r \approx 1.73\,r\f$.
  kCube,
  /// Rhombicuboctahedron with face normals in \f$\{-1,0,1\}^3\setminus 0\f$ (6 squares on the
  /// axes, 12 squares on the edge diagonals, 8 triangles), every face plane at distance >= r:
  /// vertices are the permutations of \f$(\pm t, \pm t, \pm r)\f$ with
  /// \f$t \ge (\sqrt2 - 1) r\f$ (rounded up). Circumradius \f$\approx 1.16\,r\f$.
  kRhombicuboctahedron,
};

/// "cube" / "rhombicuboctahedron" (the CLI's, the report's and the certificate's spelling).
const char* to_string(OffsetShape shape);
/// The shape spelled `text`, or nullopt.
std::optional<OffsetShape> offset_shape_from_string(std::string_view text);

}  // namespace grpvss::geometry

#pragma once
/// \file
/// \brief Limits shared by the shape builders and the mesh checks.

namespace grpvss::geometry {

/// Largest accepted |coordinate| or dimension, in model units. Beyond it a mesh or primitive
/// is almost surely in the wrong unit (millimetres read as metres), and the exact arithmetic
/// of later stages grows with the magnitudes.
inline constexpr double kMaxShapeCoordinate = 1e6;

/// Accepted range of the requested maximum relative overshoot of a circumscribed cylinder or
/// sphere polytope: below 1e-3 the polytopes grow past ~3,000 vertices.
inline constexpr double kMinRelativeOvershoot = 1e-3;
inline constexpr double kMaxRelativeOvershoot = 1.0;
/// Default maximum relative overshoot: 1% of the radius.
inline constexpr double kDefaultRelativeOvershoot = 0.01;

}  // namespace grpvss::geometry

#include "grpvss/geometry/offset_shape.hpp"

namespace grpvss::geometry {

const char* to_string(OffsetShape shape) {
  return shape == OffsetShape::kCube ? "cube" : "rhombicuboctahedron";
}

std::optional<OffsetShape> offset_shape_from_string(std::string_view text) {
  if (text == "cube") return OffsetShape::kCube;
  if (text == "rhombicuboctahedron") return OffsetShape::kRhombicuboctahedron;
  return std::nullopt;
}

}  // namespace grpvss::geometry

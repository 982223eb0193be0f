#pragma once
// The default window of the SVG picture of a report: the thesis's -50..50 (inches, the IBM 7545's
// scale) when the scene is of that size, else a window fitted to the scene (a robot in metres
// spans about 2, one in millimetres about 2000).
#include <array>

#include <nlohmann/json.hpp>

namespace grpvss::app {

/// Largest distance from the world origin over the obstacle vertices and the link frame
/// origins of the start and every step of the report's scene (0 without a scene).
double scene_extent(const nlohmann::json& report);

/// {-50, 50} when 10 <= scene_extent <= 100 (or there is no scene); else +-(1.05 x extent)
/// rounded up to two significant digits (the view's rotation keeps every point inside).
std::array<double, 2> default_svg_window(const nlohmann::json& report);

}  // namespace grpvss::app

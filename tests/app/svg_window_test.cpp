// The SVG picture's default window (app/svg_window.hpp): the thesis's -50..50 for a scene of
// the IBM 7545's inch scale, else +-(1.05 x extent) rounded up to two significant digits.
#include <array>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "interactive/svg_window.hpp"

namespace {

using grpvss::app::default_svg_window;
using grpvss::app::scene_extent;

/// A scene with one obstacle vertex and one step whose link frame 1 sits at `origin`.
nlohmann::json scene(const std::array<double, 3>& vertex, const std::array<double, 3>& origin) {
  nlohmann::json identity = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
  nlohmann::json frame = identity;
  frame[3] = origin[0];
  frame[7] = origin[1];
  frame[11] = origin[2];
  return {{"scene",
           {{"obstacles", {{{"vertices_W", {{vertex[0], vertex[1], vertex[2]}}}}}},
            {"start", {{"X_WL", {identity}}}},
            {"steps", {{{"X_WL", {identity, frame}}}}}}}};
}

TEST(SvgWindow, ExtentIsTheFarthestObstacleVertexOrFrameOrigin) {
  EXPECT_EQ(scene_extent(scene({0.0, -1.25, 0.0}, {0.5, 0.0, 0.9})), 1.25);
  EXPECT_EQ(scene_extent(scene({3.0, 4.0, 0.0}, {0.5, 0.0, 0.9})), 5.0);
  EXPECT_EQ(scene_extent(scene({0.3, 0.2, 0.2}, {0.0, 0.6, -0.8})), 1.0);
  EXPECT_EQ(scene_extent(nlohmann::json::object()), 0.0);
}

TEST(SvgWindow, ThesisSizedScenesKeepTheThesisWindowOthersAreFitted) {
  EXPECT_EQ(default_svg_window(scene({40, 0, 0}, {0, 0, 30})), (std::array<double, 2>{-50, 50}));
  EXPECT_EQ(default_svg_window(scene({10, 0, 0}, {0, 0, 0})), (std::array<double, 2>{-50, 50}));
  EXPECT_EQ(default_svg_window(scene({100, 0, 0}, {0, 0, 0})), (std::array<double, 2>{-50, 50}));
  EXPECT_EQ(default_svg_window(nlohmann::json::object()), (std::array<double, 2>{-50, 50}));
  // A robot in metres: 1.05 x 2 = 2.1; 1.05 x 0.8 = 0.84.
  EXPECT_DOUBLE_EQ(default_svg_window(scene({0.0, -2.0, 0.0}, {0.5, 0.0, 0.9}))[1], 2.1);
  EXPECT_DOUBLE_EQ(default_svg_window(scene({0.8, 0, 0}, {0, 0, 0.5}))[0], -0.84);
  // In millimetres: 1.05 x 1500 = 1575 -> 1600.
  EXPECT_DOUBLE_EQ(default_svg_window(scene({1500, 0, 0}, {0, 0, 800}))[1], 1600);
}

}  // namespace

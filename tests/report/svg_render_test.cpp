#include "grpvss/report/svg_render.hpp"

#include <regex>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "grpvss/common/input_error.hpp"
#include "support/text_files.hpp"

namespace grpvss::report {
namespace {

using nlohmann::json;

const std::string kGolden = std::string(GRPVSS_SOURCE_DIR) + "/tests/report/golden/svg_small.svg";

json identity_pose() { return json::array({1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1}); }

/// A robot of one link (a 10-cube) translated by (5, 0, 0) at step 2, one tetrahedral obstacle,
/// one interference point at step 2.
json small_report() {
  const json cube_vertices = json::array({{0, 0, 0}, {10, 0, 0}, {10, 10, 0}, {0, 10, 0},
                                          {0, 0, 10}, {10, 0, 10}, {10, 10, 10}, {0, 10, 10}});
  const json cube_edges = json::array({{0, 1}, {1, 2}, {2, 3}, {0, 3}, {4, 5}, {5, 6}, {6, 7},
                                       {4, 7}, {0, 4}, {1, 5}, {2, 6}, {3, 7}});
  json moved = identity_pose();
  moved[3] = 5;
  return {
      {"schema", "grpvss-report/1"},
      {"robot", {{"name", "CUBE<&>"}, {"joint_count", 0}}},
      {"verdict", "COLLISION"},
      {"steps",
       {{{"index", 1}, {"segment", 1}, {"path_time", 0.0}, {"interference_points", json::array()}},
        {{"index", 2},
         {"segment", 1},
         {"path_time", 0.5},
         {"interference_points", {{{"point", {10, 20, 5}}}}}}}},
      {"scene",
       {{"links", {{{"link", 0}, {"hulls", {{{"vertices_L", cube_vertices}, {"edges", cube_edges}}}}}}},
        {"obstacles",
         {{{"vertices_W", {{20, 0, 0}, {30, 0, 0}, {20, 10, 0}, {20, 0, 10}}},
           {"edges", {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}}}}}},
        {"steps", {{{"step", 1}, {"X_WL", {identity_pose()}}}, {{"step", 2}, {"X_WL", {moved}}}}}}}};
}

int count(const std::string& text, const std::string& pattern) {
  const std::regex re(pattern);
  return static_cast<int>(std::distance(std::sregex_iterator(text.begin(), text.end(), re),
                                        std::sregex_iterator()));
}

TEST(SvgRender, MatchesTheGoldenFileForTheThesisDefaultView) {
  const std::string svg = render_step_svg(small_report(), 2, SvgView{}, "small.json");
  EXPECT_EQ(svg, test::read_text_file(kGolden));
}

TEST(SvgRender, OnePathPerHullAndObstacleAndOneStarPerInterferencePoint) {
  const std::string svg = render_step_svg(small_report(), 2, SvgView{}, "small.json");
  EXPECT_EQ(count(svg, "<path class=\"link\""), 1);
  EXPECT_EQ(count(svg, "<path class=\"obstacle\""), 1);
  EXPECT_EQ(count(svg, "<polygon class=\"star\""), 1);
  EXPECT_EQ(count(svg, "M[-0-9.]+ [-0-9.]+L"), 12 + 6);  // one move-line pair per edge
  EXPECT_NE(svg.find("CUBE&lt;&amp;&gt;"), std::string::npos);  // names are escaped
  const std::string first = render_step_svg(small_report(), 1, SvgView{}, "small.json");
  EXPECT_EQ(count(first, "<polygon class=\"star\""), 0);
  EXPECT_NE(first, svg);  // the link moved
}

TEST(SvgRender, ProjectionFollowsTheThesisAngleConvention) {
  // Angles 0: screen = world x right, y up; window -50..50 on 600 px: pixel = 6 (x + 50), 6 (50 - y).
  SvgView front;
  front.angle_x_deg = front.angle_z_deg = 0.0;
  // Star at (10, 20, 5): centre (360, 180), top point 7 px above.
  EXPECT_NE(render_step_svg(small_report(), 2, front, "r").find("points=\"360.00,173.00 "),
            std::string::npos);
  // ANGLEZ 90: world x turns onto screen y, so (10, 20, 5) lands at screen (-20, 10).
  SvgView turned = front;
  turned.angle_z_deg = 90.0;
  EXPECT_NE(render_step_svg(small_report(), 2, turned, "r").find("points=\"180.00,233.00 "),
            std::string::npos);
  // ANGLEX -90: world z points up the screen: (10, 20, 5) at screen (10, 5).
  SvgView up = front;
  up.angle_x_deg = -90.0;
  EXPECT_NE(render_step_svg(small_report(), 2, up, "r").find("points=\"360.00,263.00 "),
            std::string::npos);
  // Shift before scale: scale 2 about the shifted origin (10, 20, 0) puts the star at (0, 0).
  SvgView zoom = front;
  zoom.scale = 2.0;
  zoom.shift = {10.0, 20.0, 0.0};
  EXPECT_NE(render_step_svg(small_report(), 2, zoom, "r").find("points=\"300.00,293.00 "),
            std::string::npos);
}

const std::string kNamedGolden = std::string(GRPVSS_SOURCE_DIR) + "/tests/report/golden/svg_named.svg";

/// small_report() as a cell's report: the link, its hull and the obstacle named (a name that
/// needs escaping), indices as the verifier writes them, and a start configuration (step 0).
json named_report() {
  json report = small_report();
  json& scene = report["scene"];
  scene["links"][0]["name"] = "arm<1>";
  scene["links"][0]["hulls"][0]["hull"] = 0;
  scene["links"][0]["hulls"][0]["name"] = "arm<1>";
  scene["obstacles"][0]["obstacle"] = 0;
  scene["obstacles"][0]["name"] = "post & beam";
  report["steps"][1]["interference_points"][0]["link"] = 0;
  report["steps"][1]["interference_points"][0]["hull"] = 0;
  report["steps"][1]["interference_points"][0]["obstacle"] = 0;
  json start = identity_pose();
  start[7] = -30;  // y shifted by -30 at the start
  scene["start"] = {{"step", 0}, {"X_WL", {start}}};
  return report;
}

TEST(SvgRender, NamedLinksObstaclesAndStarsCarryTitlesAndMatchTheGoldenFile) {
  const std::string svg = render_step_svg(named_report(), 2, SvgView{}, "named.json");
  EXPECT_EQ(svg, test::read_text_file(kNamedGolden));
  // <title> children give the browser's hover tooltip: name, index, hull.
  EXPECT_EQ(count(svg, "<title>arm&lt;1&gt; \\(link 0\\), hull 0</title></path>"), 1);
  EXPECT_EQ(count(svg, "<title>post &amp; beam \\(obstacle 0\\)</title></path>"), 1);
  EXPECT_EQ(count(svg, "<title>arm&lt;1&gt; hull 0 / post &amp; beam</title></polygon>"), 1);
  EXPECT_EQ(count(svg, "<title>"), 3);
  // Without names (thesis reports) no element has a title: the golden file above stays.
  EXPECT_EQ(count(render_step_svg(small_report(), 2, SvgView{}, "r"), "<title>"), 0);
}

TEST(SvgRender, StepZeroIsTheStartConfigurationWhenTheSceneHasOne) {
  SvgView front;
  front.angle_x_deg = front.angle_z_deg = 0.0;
  const std::string start = render_step_svg(named_report(), 0, front, "named.json");
  // The cube's corner (0, 0, 0) moved to (0, -30, 0): pixel (6 * 50, 6 * (50 + 30)) = (300, 480).
  EXPECT_NE(start.find("M300.00 480.00L360.00 480.00"), std::string::npos) << start;
  EXPECT_NE(start.find("step 0 - t = 0.000 s - segment 0 - interference points: 0"),
            std::string::npos);
  EXPECT_EQ(count(start, "<polygon class=\"star\""), 0);
  // A report without a start has no step 0.
  EXPECT_THROW(render_step_svg(small_report(), 0, front, "r.json"), InputError);
}

TEST(SvgRender, BadStepsViewsAndReportsAreInputErrors) {
  EXPECT_THROW(render_step_svg(small_report(), 3, SvgView{}, "r.json"), InputError);
  SvgView window;
  window.window_min = 5.0;
  window.window_max = 5.0;
  EXPECT_THROW(render_step_svg(small_report(), 1, window, "r.json"), InputError);
  SvgView scale;
  scale.scale = 0.0;
  EXPECT_THROW(render_step_svg(small_report(), 1, scale, "r.json"), InputError);
  json broken = small_report();
  broken["scene"].erase("obstacles");
  try {
    render_step_svg(broken, 1, SvgView{}, "r.json");
    FAIL() << "no error";
  } catch (const InputError& error) {
    EXPECT_EQ(error.file(), "r.json");
  }
}

}  // namespace
}  // namespace grpvss::report

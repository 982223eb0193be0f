#include "grpvss/report/svg_render.hpp"

#include <cmath>
#include <string>
#include <vector>

#include <Eigen/Geometry>
#include <fmt/core.h>
#include <nlohmann/json.hpp>

#include "grpvss/common/input_error.hpp"
#include "grpvss/report/markup_escape.hpp"

namespace grpvss::report {

namespace {

using nlohmann::json;
constexpr double kPi = 3.14159265358979323846;

/// Fixed 2-decimal text; "-0.00" becomes "0.00" so that output never depends on signed zeros.
std::string number(double value) {
  std::string text = fmt::format("{:.2f}", value);
  if (text == "-0.00") text = "0.00";
  return text;
}

/// Shortest text for a view parameter (at most 6 significant digits), e.g. "-75", "1.5".
std::string short_number(double value) {
  std::string text = fmt::format("{:.6g}", value);
  if (text == "-0") text = "0";
  return text;
}

Eigen::Vector3d point3(const json& value) {
  return {value.at(0).get<double>(), value.at(1).get<double>(), value.at(2).get<double>()};
}

Eigen::Isometry3d pose(const json& rows) {
  Eigen::Matrix4d m;
  for (int r = 0; r < 4; ++r) {
    for (int c = 0; c < 4; ++c) m(r, c) = rows.at(4 * r + c).get<double>();
  }
  Eigen::Isometry3d X;
  X.matrix() = m;
  return X;
}

class Projector {
 public:
  explicit Projector(const SvgView& view) : view_(view) {
    const auto rad = [](double deg) { return deg * kPi / 180.0; };
    R_SW_ = (Eigen::AngleAxisd(rad(view.angle_x_deg), Eigen::Vector3d::UnitX()) *
             Eigen::AngleAxisd(rad(view.angle_y_deg), Eigen::Vector3d::UnitY()) *
             Eigen::AngleAxisd(rad(view.angle_z_deg), Eigen::Vector3d::UnitZ()))
                .toRotationMatrix();
    shift_W_ = {view.shift[0], view.shift[1], view.shift[2]};
  }
  /// Picture coordinates (pixels, y down) of a world point.
  Eigen::Vector2d operator()(const Eigen::Vector3d& p_W) const {
    const Eigen::Vector3d p_S = view_.scale * (R_SW_ * (p_W - shift_W_));
    const double span = view_.window_max - view_.window_min;
    return {(p_S.x() - view_.window_min) / span * view_.pixels,
            (view_.window_max - p_S.y()) / span * view_.pixels};
  }

 private:
  SvgView view_;
  Eigen::Matrix3d R_SW_;
  Eigen::Vector3d shift_W_;
};

/// The element's name when the report gives one (cells), else "" (thesis reports unchanged).
std::string name_of(const json& element) {
  return element.contains("name") ? element.at("name").get<std::string>() : std::string();
}

/// `<title>` (the browser's hover tooltip) for a named element; "" when `text` is empty.
std::string title(const std::string& text) {
  return text.empty() ? std::string() : "<title>" + markup_escape(text) + "</title>";
}

/// "name (link 3), hull 1" (with the hull's own name after it when it differs) / "name
/// (obstacle 7)" for a named element, "" without a name.
std::string link_title(const json& link, const json& hull) {
  const std::string name = name_of(link);
  if (name.empty()) return "";
  const std::string hull_name = name_of(hull);
  return fmt::format("{} (link {}), hull {}{}", name, link.at("link").get<int>(),
                     hull.at("hull").get<int>(),
                     hull_name.empty() || hull_name == name ? "" : " (" + hull_name + ")");
}

std::string obstacle_title(const json& obstacle) {
  const std::string name = name_of(obstacle);
  if (name.empty()) return "";
  return fmt::format("{} (obstacle {})", name, obstacle.at("obstacle").get<int>());
}

/// True when some link or obstacle of the scene has a name (a cell's report).
bool has_names(const json& scene) {
  for (const json& link : scene.at("links")) {
    if (link.contains("name")) return true;
  }
  for (const json& obstacle : scene.at("obstacles")) {
    if (obstacle.contains("name")) return true;
  }
  return false;
}

/// "link_4 hull 0 / post" for an interference point when the report has names, else "".
std::string point_title(const json& scene, const json& point) {
  if (!has_names(scene)) return "";
  const json& link = scene.at("links").at(point.at("link").get<std::size_t>());
  const json& obstacle = scene.at("obstacles").at(point.at("obstacle").get<std::size_t>());
  if (name_of(link).empty() && name_of(obstacle).empty()) return "";
  const auto or_index = [](const std::string& name, const char* what, int index) {
    return name.empty() ? fmt::format("{} {}", what, index) : name;
  };
  return fmt::format("{} hull {} / {}", or_index(name_of(link), "link", link.at("link").get<int>()),
                     point.at("hull").get<int>(),
                     or_index(name_of(obstacle), "obstacle", obstacle.at("obstacle").get<int>()));
}

/// An SVG element, with its title as a child when it has one.
std::string element(const std::string& open, const std::string& title_text) {
  if (title_text.empty()) return open + "/>\n";
  return open + ">" + title(title_text) + "</" + open.substr(1, open.find(' ') - 1) + ">\n";
}

/// All edges of one polytope as one SVG path (titled with its name when it has one).
std::string edge_path(const std::vector<Eigen::Vector3d>& vertices_W, const json& edges,
                      const Projector& project, const char* css_class,
                      const std::string& title_text) {
  std::string d;
  for (const json& edge : edges) {
    const Eigen::Vector2d a = project(vertices_W.at(edge.at(0).get<std::size_t>()));
    const Eigen::Vector2d b = project(vertices_W.at(edge.at(1).get<std::size_t>()));
    d += fmt::format("M{} {}L{} {}", number(a.x()), number(a.y()), number(b.x()), number(b.y()));
  }
  return element(fmt::format("<path class=\"{}\" d=\"{}\"", css_class, d), title_text);
}

/// A five-pointed star centred on c (outer radius 7 px).
std::string star(const Eigen::Vector2d& c, const std::string& title_text) {
  std::string points;
  for (int k = 0; k < 10; ++k) {
    const double radius = k % 2 == 0 ? 7.0 : 2.8;
    const double angle = -kPi / 2 + k * kPi / 5;
    if (k > 0) points += ' ';
    points += number(c.x() + radius * std::cos(angle)) + "," + number(c.y() + radius * std::sin(angle));
  }
  return element(fmt::format("<polygon class=\"star\" points=\"{}\"", points), title_text);
}

/// The step drawn: a record of `steps` with its scene poses, or step 0, the start
/// configuration (the scene's `start` poses; the report has no interference points there).
struct StepView {
  json step;
  json X_WL;
};

StepView step_view(const json& report, int step_index) {
  const json& scene = report.at("scene");
  if (step_index == 0 && scene.contains("start") && !scene.at("start").is_null()) {
    return {{{"path_time", 0.0}, {"segment", 0}, {"interference_points", json::array()}},
            scene.at("start").at("X_WL")};
  }
  const json& steps = report.at("steps");
  std::size_t k = 0;
  while (k < steps.size() && steps.at(k).at("index").get<int>() != step_index) ++k;
  if (k == steps.size()) {
    throw std::out_of_range(fmt::format("step {} is not in the report", step_index));
  }
  return {steps.at(k), scene.at("steps").at(k).at("X_WL")};
}

std::string render(const json& report, int step_index, const SvgView& view) {
  const json& scene = report.at("scene");
  const StepView shown = step_view(report, step_index);
  const json& step = shown.step;
  const json& poses = shown.X_WL;
  const Projector project(view);
  std::string body;
  for (const json& obstacle : scene.at("obstacles")) {
    std::vector<Eigen::Vector3d> vertices_W;
    for (const json& v : obstacle.at("vertices_W")) vertices_W.push_back(point3(v));
    body += edge_path(vertices_W, obstacle.at("edges"), project, "obstacle", obstacle_title(obstacle));
  }
  for (const json& link : scene.at("links")) {
    const Eigen::Isometry3d X_WL = pose(poses.at(link.at("link").get<std::size_t>()));
    for (const json& hull : link.at("hulls")) {
      std::vector<Eigen::Vector3d> vertices_W;
      for (const json& v : hull.at("vertices_L")) vertices_W.push_back(X_WL * point3(v));
      body += edge_path(vertices_W, hull.at("edges"), project, "link", link_title(link, hull));
    }
  }
  for (const json& point : step.at("interference_points")) {
    body += star(project(point3(point.at("point"))), point_title(scene, point));
  }

  const int size = view.pixels;
  const int caption = 54;
  std::string svg = fmt::format(
      "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{0}\" height=\"{1}\" "
      "viewBox=\"0 -{2} {0} {1}\">\n"
      "<style>.link{{fill:none;stroke:#1d3557;stroke-width:1}}"
      ".obstacle{{fill:none;stroke:#2f6f2f;stroke-width:1}}"
      ".star{{fill:#e01010;stroke:#600000;stroke-width:0.5}}"
      "text{{font-family:monospace;font-size:11px;fill:#111}}</style>\n"
      "<rect x=\"0\" y=\"-{2}\" width=\"{0}\" height=\"{1}\" fill=\"#ffffff\"/>\n"
      "<rect x=\"0\" y=\"0\" width=\"{0}\" height=\"{0}\" fill=\"none\" stroke=\"#999\"/>\n",
      size, size + caption, caption);
  svg += fmt::format("<text x=\"6\" y=\"-40\">GRPVSS {} - verdict {}</text>\n",
                     markup_escape(report.at("robot").at("name").get<std::string>()),
                     markup_escape(report.at("verdict").get<std::string>()));
  svg += fmt::format(
      "<text x=\"6\" y=\"-25\">step {} - t = {} s - segment {} - interference points: {}</text>\n",
      step_index, fmt::format("{:.3f}", step.at("path_time").get<double>()),
      step.at("segment").get<int>(), step.at("interference_points").size());
  svg += fmt::format(
      "<text x=\"6\" y=\"-10\">ANGLEX {} ANGLEY {} ANGLEZ {} SCALE {} SHIFT {},{},{} WINDOW {}..{}</text>\n",
      short_number(view.angle_x_deg), short_number(view.angle_y_deg),
      short_number(view.angle_z_deg), short_number(view.scale), short_number(view.shift[0]),
      short_number(view.shift[1]), short_number(view.shift[2]), short_number(view.window_min),
      short_number(view.window_max));
  svg += fmt::format("<svg x=\"0\" y=\"0\" width=\"{0}\" height=\"{0}\" viewBox=\"0 0 {0} {0}\" overflow=\"hidden\">\n", size);
  svg += body;
  svg += "</svg>\n</svg>\n";
  return svg;
}

}  // namespace

std::string render_step_svg(const nlohmann::json& report, int step, const SvgView& view,
                            const std::string& report_file) {
  if (!(view.window_min < view.window_max) || !std::isfinite(view.window_min) ||
      !std::isfinite(view.window_max)) {
    throw InputError(report_file, 0, "a window lo,hi with lo < hi",
                     fmt::format("{},{}", view.window_min, view.window_max));
  }
  if (!(view.scale > 0) || !std::isfinite(view.scale)) {
    throw InputError(report_file, 0, "a scale > 0", fmt::format("{}", view.scale));
  }
  if (view.pixels < 16) throw InputError(report_file, 0, "a picture of >= 16 pixels");
  try {
    return render(report, step, view);
  } catch (const std::out_of_range& error) {
    throw InputError(report_file, 0, "a report step with this index and its scene pose",
                     error.what());
  } catch (const nlohmann::json::exception& error) {
    throw InputError(report_file, 0, "a GRPVSS report with a scene (docs/report-schema.md)",
                     error.what());
  }
}

}  // namespace grpvss::report

#include "interactive/svg_window.hpp"

#include <algorithm>
#include <cmath>

namespace grpvss::app {
namespace {

constexpr double kThesisHalfWindow = 50.0;

/// Distance of the origin of a row-major 4x4 X_WL (as the scene stores it) from the world's.
double origin_extent(const nlohmann::json& X_WL) {
  if (!X_WL.is_array() || X_WL.size() != 16) return 0.0;
  return std::hypot(X_WL[3].get<double>(), X_WL[7].get<double>(), X_WL[11].get<double>());
}

double frames_extent(const nlohmann::json& state) {
  double extent = 0.0;
  if (!state.is_object() || !state.contains("X_WL")) return extent;
  for (const nlohmann::json& X_WL : state["X_WL"]) extent = std::max(extent, origin_extent(X_WL));
  return extent;
}

/// value (> 0) rounded up to two significant digits.
double round_up_two_digits(double value) {
  const double unit = std::pow(10.0, std::floor(std::log10(value)) - 1.0);
  return std::ceil(value / unit) * unit;
}

}  // namespace

double scene_extent(const nlohmann::json& report) {
  if (!report.contains("scene")) return 0.0;
  const nlohmann::json& scene = report["scene"];
  double extent = 0.0;
  for (const nlohmann::json& obstacle : scene.value("obstacles", nlohmann::json::array())) {
    for (const nlohmann::json& p : obstacle.value("vertices_W", nlohmann::json::array())) {
      if (p.size() != 3) continue;
      extent = std::max(extent, std::hypot(p[0].get<double>(), p[1].get<double>(),
                                           p[2].get<double>()));
    }
  }
  extent = std::max(extent, frames_extent(scene.value("start", nlohmann::json::object())));
  for (const nlohmann::json& step : scene.value("steps", nlohmann::json::array())) {
    extent = std::max(extent, frames_extent(step));
  }
  return extent;
}

std::array<double, 2> default_svg_window(const nlohmann::json& report) {
  const double extent = scene_extent(report);
  if (extent == 0.0 || (extent >= 10.0 && extent <= 100.0)) {
    return {-kThesisHalfWindow, kThesisHalfWindow};
  }
  // Any rotation keeps a point's distance from the origin: every projected x, y fits.
  const double half = round_up_two_digits(1.05 * extent);
  return {-half, half};
}

}  // namespace grpvss::app

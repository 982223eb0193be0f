#pragma once
/// \file
/// \brief The thesis's wireframe picture of one simulation step as SVG (docs/viewer.md#svg).
///
/// View as in the thesis (A.2, "ENTER ANGLEX, ANGLE Y, ANGLE Z"): the screen frame S has x to
/// the right, y up and z out of the screen; the world frame starts aligned with S and turns
/// ANGLEX about its x axis, then ANGLEY about the new y axis, then ANGLEZ about the new z axis,
/// so \f$p_S = s\,R_x(a_x) R_y(a_y) R_z(a_z)\,(p_W - t)\f$ (shift t applied before the scale s,
/// in original dimensions). The window [lo, hi] of S's x and y fills the picture; depth is
/// dropped (orthographic, all edges drawn, as the thesis's wireframe display did).

#include <array>
#include <string>

#include <nlohmann/json_fwd.hpp>

namespace grpvss::report {

/// View parameters; the defaults are the thesis's (-75, 0, 170 deg; scale 1; window -50..50).
struct SvgView {
  double angle_x_deg = -75.0;
  double angle_y_deg = 0.0;
  double angle_z_deg = 170.0;
  double scale = 1.0;
  std::array<double, 3> shift{0.0, 0.0, 0.0};
  double window_min = -50.0;
  double window_max = 50.0;
  int pixels = 600;  ///< width and height of the drawing area
};

/// \brief SVG text of step `step` (the report's 1-based step index) of a JSON report with a
/// `scene` object: obstacles (green), link hulls (blue) as wireframes, the step's interference
/// points as red stars, a caption. Deterministic: coordinates printed with 2 decimals.
/// \throws InputError (file = `report_file`) when the step does not exist, the report lacks a
/// field, or the view is invalid (window_min >= window_max, scale <= 0, pixels < 16).
std::string render_step_svg(const nlohmann::json& report, int step, const SvgView& view,
                            const std::string& report_file);

}  // namespace grpvss::report

#pragma once
/// \file
/// \brief The view of the animation (thesis A.2.2): rotation angles, scale and window shift,
/// and stepping or continuous motion. Stored for the animation/SVG renderer.

#include <array>

namespace grpvss::app::interactive {

struct ViewSettings {
  /// Degrees: rotate ANGLEX about the current X axis (X right, Z out of the screen), then ANGLEY
  /// about the new Y, then ANGLEZ about the new Z. Thesis default -75, 0, 170.
  std::array<double, 3> angles_deg{-75.0, 0.0, 170.0};
  /// Scale factor (> 0) applied after the shift; thesis default 1.
  double scale = 1.0;
  /// Window shift in original (file) length units, applied before scaling; default 0, 0, 0.
  /// The unscaled view spans -50..50 in each dimension.
  std::array<double, 3> shift{0.0, 0.0, 0.0};
  /// Stepping motion (the user advances each step) instead of continuous motion.
  bool stepping = false;
};

}  // namespace grpvss::app::interactive

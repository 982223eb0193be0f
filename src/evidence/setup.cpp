#include "grpvss/evidence/setup.hpp"

namespace grpvss::certify {

VerificationSetup resolve_setup(const SetupRequest& request) {
  VerificationSetup setup;
  setup.cell.tolerance = request.tolerance;
  // The thesis's edge offset sqrt(2) Delta is the cube's; the certified default is the tighter
  // rhombicuboctahedron (proofs/tolerance-offset.md).
  setup.cell.offset_shape = request.offset_shape.value_or(
      request.mode == ResolutionMode::kThesis ? geometry::OffsetShape::kCube
                                              : geometry::OffsetShape::kRhombicuboctahedron);
  setup.run.mode = request.mode;
  setup.run.motion = request.motion;
  setup.run.cp_model = request.cp_model;
  setup.run.limits = request.limits;
  setup.run.claim = request.claim;
  setup.run.path_label = request.path_label;
  return setup;
}

}  // namespace grpvss::certify

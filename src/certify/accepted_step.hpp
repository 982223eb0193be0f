#pragma once
// What the march hands to the recorders for every step it accepts.

#include "cell_probe.hpp"
#include "grpvss/evidence/certificate.hpp"

namespace grpvss::certify {

struct AcceptedStep {
  const ProbeResult& from;  ///< the previous step's probe
  const ProbeResult& to;    ///< this step's probe (with its interference points)
  const TransitionRecord& transition;  ///< judged from `from` to `to`
  int segment = 0;          ///< 1-based
  double parameter = 0.0;   ///< segment parameter of `to`
  double path_time = 0.0;   ///< s from the start of the path
  bool refinement = false;  ///< inserted next to a contact (Section 5.2.2)
};

}  // namespace grpvss::certify

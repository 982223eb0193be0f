#include "grpvss/motion/motion_model.hpp"

namespace grpvss::motion {

const char* to_string(PtpTiming timing) {
  return timing == PtpTiming::kSynchronized ? "synchronized" : "independent";
}

std::optional<PtpTiming> ptp_timing_from_string(std::string_view text) {
  if (text == "independent") return PtpTiming::kIndependent;
  if (text == "synchronized") return PtpTiming::kSynchronized;
  return std::nullopt;
}

}  // namespace grpvss::motion

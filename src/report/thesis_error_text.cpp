#include "thesis_error_text.hpp"

#include <stdexcept>

#include <fmt/core.h>

#include "grpvss/motion/thesis_error.hpp"

namespace grpvss::report {

// One wording of Appendix A.4 in the project: motion::thesis_error_text. The report adds the
// stricter contract its callers need (a segment number wherever A.4 prints "I").
std::string thesis_error_text(int code, int segment) {
  if (!is_thesis_error_code(code)) {
    throw std::out_of_range(fmt::format("thesis_error_text: no thesis error {} (1-6)", code));
  }
  if (code >= 3 && segment < 1) {
    throw std::out_of_range(
        fmt::format("thesis_error_text: error {} needs a segment number >= 1, got {}", code,
                    segment));
  }
  return motion::thesis_error_text(code, segment);
}

}  // namespace grpvss::report

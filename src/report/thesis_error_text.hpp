#pragma once
/// \file
/// \brief The thesis's error descriptions (Appendix A.4, errors 1-6), word for word.

#include <string>

namespace grpvss::report {

/// Lowest and highest error code the thesis defines; codes >= 7 are GRPVSS's own detections.
inline constexpr int kFirstThesisErrorCode = 1;
inline constexpr int kLastThesisErrorCode = 6;

/// \brief The A.4 description of thesis error `code` (1-6).
///
/// Errors 3-6 name the motion segment ("the number I will be returned along with the error
/// message for Error 3 - Error 6"): the thesis's placeholder I is replaced by `segment`.
/// Errors 1 and 2 are path-wide and ignore `segment`.
///
/// \throws std::out_of_range if `code` is not 1-6, or if `code` is 3-6 and `segment` < 1
///         (both are programming errors: the caller decides which error occurred).
std::string thesis_error_text(int code, int segment);

/// True for the codes 1-6 that thesis_error_text() describes.
constexpr bool is_thesis_error_code(int code) {
  return code >= kFirstThesisErrorCode && code <= kLastThesisErrorCode;
}

}  // namespace grpvss::report

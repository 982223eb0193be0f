#pragma once
// Shared by the fuzz targets: the input bytes as text, and the IBM 7545 sample files that the
// path and checker targets parse against (read once per process).
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "grpvss/io/text_file.hpp"

namespace grpvss::fuzz {

inline std::string_view as_text(const std::uint8_t* data, std::size_t size) {
  return {reinterpret_cast<const char*>(data), size};
}

/// A file of the source tree, e.g. sample_file("data/ibm7545/robot.txt").
inline std::string sample_file(const std::string& relative) {
  return io::read_text_file(std::string(GRPVSS_SOURCE_DIR) + "/" + relative);
}

}  // namespace grpvss::fuzz

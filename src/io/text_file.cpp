#include "grpvss/io/text_file.hpp"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <iterator>

#include "grpvss/common/input_error.hpp"

namespace grpvss::io {

std::string read_text_file(const std::string& path) {
  std::ifstream stream(path, std::ios::binary);
  if (!stream) throw InputError(path, 0, "a readable file", std::strerror(errno));
  stream.seekg(0, std::ios::end);
  const std::streamoff size = stream.tellg();
  if (size < 0) throw InputError(path, 0, "a readable file", "a stream without a size");
  // Checked before allocating, so a huge file fails fast.
  if (static_cast<unsigned long long>(size) > kMaxInputFileBytes) {
    throw InputError(path, 0, "a file of at most " + std::to_string(kMaxInputFileBytes) + " bytes",
                     std::to_string(size) + " bytes");
  }
  stream.seekg(0, std::ios::beg);
  std::string text(static_cast<std::size_t>(size), '\0');
  if (size > 0 && !stream.read(text.data(), size)) {
    throw InputError(path, 0, "a readable file", "a read error");
  }
  return text;
}

}  // namespace grpvss::io

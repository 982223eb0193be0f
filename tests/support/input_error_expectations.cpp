#include "support/input_error_expectations.hpp"

#include <fstream>
#include <sstream>
#include <stdexcept>

namespace grpvss::testing {

std::string source_file_text(const std::string& relative_path) {
  std::ifstream stream(std::string(GRPVSS_SOURCE_DIR) + "/" + relative_path, std::ios::binary);
  if (!stream) throw std::runtime_error("cannot open " + relative_path);
  std::ostringstream buffer;
  buffer << stream.rdbuf();
  return buffer.str();
}

std::string with_line_replaced(const std::string& text, int line, const std::string& content) {
  std::size_t start = 0;
  for (int i = 1; i < line; ++i) {
    start = text.find('\n', start);
    if (start == std::string::npos) throw std::out_of_range("with_line_replaced: no such line");
    ++start;
  }
  const std::size_t stop = text.find('\n', start);
  return text.substr(0, start) + content + (stop == std::string::npos ? "" : text.substr(stop));
}

std::string first_lines(const std::string& text, int lines) {
  std::size_t stop = 0;
  for (int i = 0; i < lines; ++i) {
    stop = text.find('\n', stop);
    if (stop == std::string::npos) throw std::out_of_range("first_lines: too few lines");
    ++stop;
  }
  return text.substr(0, stop);
}

}  // namespace grpvss::testing

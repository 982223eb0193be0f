#include "grpvss/common/input_error.hpp"

#include <utility>

namespace grpvss {
namespace {

std::string compose_message(const std::string& file, int line, const std::string& expected,
                            const std::string& found) {
  std::string message = file + ":" + std::to_string(line) + ": expected " + expected;
  if (!found.empty()) message += ", found " + found;
  return message;
}

}  // namespace

InputError::InputError(std::string file, int line, std::string expected, std::string found)
    : std::runtime_error(compose_message(file, line, expected, found)),
      file_(std::move(file)),
      line_(line),
      expected_(std::move(expected)),
      found_(std::move(found)) {}

}  // namespace grpvss

#include "grpvss/report/input_digests.hpp"

#include <array>
#include <fstream>

#include "grpvss/common/input_error.hpp"
#include "grpvss/common/sha256.hpp"

namespace grpvss::report {

std::string sha256_hex_of_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, 0, "a readable input file");
  Sha256 hash;
  std::array<char, 1 << 16> buffer{};
  while (in) {
    in.read(buffer.data(), buffer.size());
    hash.update(buffer.data(), static_cast<std::size_t>(in.gcount()));
  }
  if (in.bad()) throw InputError(path, 0, "a readable input file", "a read error");
  return hash.hex_digest();
}

InputDigests digest_input_files(const std::string& robot_file,
                                const std::string& environment_file,
                                const std::string& path_file) {
  return {{robot_file, sha256_hex_of_file(robot_file)},
          {environment_file, sha256_hex_of_file(environment_file)},
          {path_file, sha256_hex_of_file(path_file)},
          /*length_unit=*/{}};
}

}  // namespace grpvss::report

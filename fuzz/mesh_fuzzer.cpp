// Fuzz target: the triangle-mesh reader (assimp: STL binary/ASCII, OBJ, COLLADA). The first
// byte picks the file type; the rest is the file. InputError is the documented outcome of bad
// input; anything else escaping, a crash, a hang, a leak or UB is a finding.
#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <string>

#include "fuzz_input.hpp"
#include "grpvss/common/input_error.hpp"
#include "grpvss/io/mesh_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  static const char* const kExtensions[] = {".stl", ".obj", ".dae"};
  // assimp reads files only (the reader's contract is a path): one scratch file per process.
  const std::string path = "/tmp/grpvss-mesh-fuzz-" + std::to_string(::getpid()) +
                           kExtensions[data[0] % 3];
  {
    std::ofstream file(path, std::ios::binary | std::ios::trunc);
    file.write(reinterpret_cast<const char*>(data + 1), static_cast<std::streamsize>(size - 1));
  }
  try {
    (void)grpvss::io::read_mesh_file(path);
  } catch (const grpvss::InputError&) {
  }
  std::remove(path.c_str());
  return 0;
}

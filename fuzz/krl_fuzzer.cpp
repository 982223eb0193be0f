// Fuzz target: the KUKA KRL program reader (docs/robot-programs.md#kuka-krl). The input is
// the .src, a NUL byte, then the .dat (without a NUL: the .src alone).
// InputError is the documented outcome of bad input; anything else is a finding.
#include <string>
#include <vector>

#include "fuzz_input.hpp"
#include "grpvss/common/input_error.hpp"
#include "grpvss/io/krl_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view input = grpvss::fuzz::as_text(data, size);
  const std::size_t split = input.find('\0');
  std::vector<grpvss::io::KrlDataText> data_files;
  if (split != std::string_view::npos) {
    data_files.push_back({"fuzz.dat", std::string(input.substr(split + 1))});
  }
  try {
    (void)grpvss::io::parse_krl(input.substr(0, split), "fuzz.src", data_files);
  } catch (const grpvss::InputError&) {
  }
  return 0;
}

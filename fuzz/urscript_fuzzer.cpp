// Fuzz target: the URScript program reader (docs/robot-programs.md#urscript).
// InputError is the documented outcome of bad input; anything else is a finding.
#include "fuzz_input.hpp"
#include "grpvss/common/input_error.hpp"
#include "grpvss/io/urscript_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    (void)grpvss::io::parse_urscript(grpvss::fuzz::as_text(data, size), "fuzz.script");
  } catch (const grpvss::InputError&) {
  }
  return 0;
}

// Fuzz target: the cell-file reader (yaml-cpp, the schema, the unit checks). Referenced files
// are resolved but not required to exist. InputError is the documented outcome of bad input;
// anything else escaping, a crash, a leak or UB is a finding.
#include "fuzz_input.hpp"
#include "grpvss/common/input_error.hpp"
#include "grpvss/io/cell_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    const auto result = grpvss::io::parse_cell(grpvss::fuzz::as_text(data, size), "fuzz.yaml", false);
    (void)result;
  } catch (const grpvss::InputError&) {
  }
  return 0;
}

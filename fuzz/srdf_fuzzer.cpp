// Fuzz target: the SRDF allowed-collision reader. InputError is the documented outcome of bad
// input; anything else escaping, a crash, a leak or UB is a finding.
#include "fuzz_input.hpp"
#include "grpvss/common/input_error.hpp"
#include "grpvss/io/srdf_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    const auto srdf = grpvss::io::parse_srdf(grpvss::fuzz::as_text(data, size), "fuzz.srdf");
    (void)grpvss::io::srdf_links_not_in(srdf, "fuzz.srdf", {"a", "b"});
  } catch (const grpvss::InputError&) {
  }
  return 0;
}

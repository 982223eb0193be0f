// Fuzz target: the motion-time table reader (MOTFIL replacement, docs/trajectories.md), and
// the table's interpolation at a few times once it parsed. InputError is the documented
// outcome of bad input; anything else is a finding.
#include "fuzz_input.hpp"
#include "grpvss/common/input_error.hpp"
#include "grpvss/io/profile_table_file.hpp"
#include "grpvss/motion/profile_table.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    const grpvss::motion::ProfileTable table(
        grpvss::io::parse_profile_table(grpvss::fuzz::as_text(data, size), "fuzz-table.txt"));
    for (int joint = 0; joint < table.joint_count(); ++joint) {
      const double duration = table.duration(joint);
      for (const double t : {-1.0, 0.0, 0.25 * duration, 0.5 * duration, duration, duration + 1})
        (void)table.progress(joint, t);
    }
  } catch (const grpvss::InputError&) {
  }
  return 0;
}

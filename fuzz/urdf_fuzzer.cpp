// Fuzz target: the URDF reader (tinyxml2 pre-pass, urdfdom, the chain decomposition) and the
// chain built from its description. Meshes are not loaded (assimp is fuzzed upstream).
// InputError is the documented outcome of bad input; anything else escaping, a crash, a leak or
// UB is a finding.
#include "fuzz_input.hpp"
#include "grpvss/common/input_error.hpp"
#include "grpvss/io/urdf_file.hpp"
#include "grpvss/kinematics/urdf_chain.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  grpvss::io::UrdfReadOptions options;
  options.load_meshes = false;
  options.use_ros_package_path = false;
  try {
    const auto result = grpvss::io::parse_urdf(grpvss::fuzz::as_text(data, size), "fuzz.urdf", options);
    const auto chain = grpvss::kinematics::make_chain(result.description);
    for (const auto& link : result.description.links) {
      for (const auto& collision : link.collisions) {
        (void)grpvss::kinematics::compose_frame_path(collision.link_to_collision);
      }
    }
    (void)chain;
  } catch (const grpvss::InputError&) {
  }
  return 0;
}

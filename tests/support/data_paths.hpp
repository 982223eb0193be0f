#pragma once
// Folders and files of the source tree that many tests read (GRPVSS_SOURCE_DIR), named once so
// that the tests' unity batches (tests/CMakeLists.txt) hold one definition of each.

#include <string>

namespace grpvss::test {

inline const std::string kSourceDir = GRPVSS_SOURCE_DIR;
/// The thesis's IBM 7545 sample: robot.txt, environment.txt, path.txt, ...
inline const std::string kIbm7545Data = kSourceDir + "/data/ibm7545/";
inline const std::string kTestCells = kSourceDir + "/tests/data/cells/";
inline const std::string kTestPrograms = kSourceDir + "/tests/data/programs/";
inline const std::string kTestTrajectories = kSourceDir + "/tests/data/trajectories/";
/// The UR5e cell with a post and no self-collision pairs.
inline const std::string kUr5ePostNoSelfCell = kTestCells + "ur5e-post-no-self.yaml";
/// The robots shared with the sibling projects (URDFs with their meshes).
inline const std::string kSharedRobots = kSourceDir + "/../shared/robots/";

/// data/ibm7545/<name>.
inline std::string ibm7545_file(const std::string& name) { return kIbm7545Data + name; }

}  // namespace grpvss::test

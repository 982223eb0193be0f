// assimp is loaded when a run reads its first mesh (src/io/assimp_import.cpp), not at process
// start: a run without meshes never loads it, a run with one loads the library assimp's package
// names (or GRPVSS_ASSIMP_LIBRARY), and a library that cannot be loaded is an input error
// naming the mesh file and the library (exit 2), never a crash.
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "support/cli_run.hpp"
#include "support/data_paths.hpp"
#include "support/text_files.hpp"

namespace {

using grpvss::test::CliRun;
using grpvss::test::kIbm7545Data;
using grpvss::test::kTestCells;
using grpvss::test::run_cli;

constexpr const char* kMissingLibrary = "GRPVSS_ASSIMP_LIBRARY=libgrpvss-test-no-such-assimp.so.5";

class MeshLibrary : public ::testing::Test {
 protected:
  void SetUp() override {
    directory_ = grpvss::test::make_temporary_directory("mesh-library");
    // The thesis robot in inches beside a CAD bracket in mm (an STL read through assimp).
    std::ofstream(directory_ + "/mesh.yaml")
        << "units: in\nrobot:\n  thesis: " << kIbm7545Data << "robot.txt\nobstacles:\n"
        << "  - {name: bracket, mesh: " << kTestCells << "l-bracket.stl, units: mm, "
        << "pose: {xyz: [60, 0, 0]}}\n";
    std::ofstream(directory_ + "/boxes.yaml")
        << "units: in\nrobot:\n  thesis: " << kIbm7545Data << "robot.txt\nobstacles:\n"
        << "  - {name: crate, box: [2, 2, 2], pose: {xyz: [60, 0, 0]}}\n";
    std::ofstream(directory_ + "/p.txt") << "1\n1\n10.,30.\n10.,30.\n1.,1.\n10.,30.\n";
  }
  void TearDown() override { std::filesystem::remove_all(directory_); }
  CliRun verify(const std::string& cell, const std::string& environment = "") const {
    return run_cli(directory_, "verify --cell " + cell + " --path p.txt --tolerance 0.5 --no-cache",
                   environment);
  }
  std::string directory_;
};

TEST_F(MeshLibrary, ACellOfMeshesReadsThemThroughTheLibraryAssimpsPackageNames) {
  const CliRun run = verify("mesh.yaml");
  EXPECT_EQ(run.exit_code, 0) << run.out << run.err;
  EXPECT_NE(run.out.find("CLEAR"), std::string::npos) << run.out;
}

TEST_F(MeshLibrary, ARunWithoutMeshesNeverLoadsTheLibrary) {
  const CliRun run = verify("boxes.yaml", kMissingLibrary);
  EXPECT_EQ(run.exit_code, 0) << run.out << run.err;
  EXPECT_EQ(run.err.find("assimp"), std::string::npos) << run.err;
}

TEST_F(MeshLibrary, ALibraryThatCannotBeLoadedIsAnInputErrorNamingTheMeshAndTheLibrary) {
  const CliRun run = verify("mesh.yaml", kMissingLibrary);
  EXPECT_EQ(run.exit_code, 2) << run.out << run.err;
  EXPECT_NE(run.err.find("l-bracket.stl"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("expected assimp (libgrpvss-test-no-such-assimp.so.5) to read this mesh, "
                         "found it cannot be loaded: "),
            std::string::npos)
      << run.err;
  EXPECT_TRUE(run.out.empty()) << run.out;
}

}  // namespace

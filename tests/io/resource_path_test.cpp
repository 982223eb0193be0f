#include "grpvss/io/resource_path.hpp"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "support/text_files.hpp"

namespace grpvss::io {
namespace {

class ResourcePath : public ::testing::Test {
 protected:
  void SetUp() override {
    root_ = test::make_temporary_directory("resource-path");
    for (const std::string file : {"one/pkg/a.stl", "two/pkg/a.stl", "two/pkg/b.stl", "urdf/m.stl"}) {
      std::filesystem::create_directories(std::filesystem::path(root_ + "/" + file).parent_path());
      std::ofstream(root_ + "/" + file) << "x";
    }
  }
  void TearDown() override { std::filesystem::remove_all(root_); }
  std::string root_;
};

TEST_F(ResourcePath, PackageReferencesTakeTheFirstDirectoryThatHasTheFile) {
  const std::vector<std::string> directories{root_ + "/one", root_ + "/two"};
  EXPECT_EQ(resolve_resource("package://pkg/a.stl", "", directories).path, root_ + "/one/pkg/a.stl");
  const ResolvedResource b = resolve_resource("package://pkg/b.stl", "", directories);
  EXPECT_EQ(b.path, root_ + "/two/pkg/b.stl");
  EXPECT_EQ(b.tried, (std::vector<std::string>{root_ + "/one/pkg/b.stl", root_ + "/two/pkg/b.stl"}));
  // A directory that is the package itself.
  EXPECT_EQ(resolve_resource("package://pkg/b.stl", "", {root_ + "/two/pkg/"}).path, root_ + "/two/pkg/b.stl");
  const ResolvedResource missing = resolve_resource("package://pkg/c.stl", "", directories);
  EXPECT_TRUE(missing.path.empty());
  EXPECT_EQ(missing.tried.size(), 2u);
  EXPECT_TRUE(resolve_resource("package://pkg", "", directories).path.empty());
  EXPECT_TRUE(resolve_resource("package:///a.stl", "", directories).tried.empty());
}

TEST_F(ResourcePath, FileReferencesAndPlainPathsAreTakenAgainstTheBaseDirectory) {
  EXPECT_EQ(resolve_resource("m.stl", root_ + "/urdf", {}).path, root_ + "/urdf/m.stl");
  EXPECT_EQ(resolve_resource("../urdf/./m.stl", root_ + "/one", {}).path, root_ + "/urdf/m.stl");
  EXPECT_EQ(resolve_resource("file://" + root_ + "/urdf/m.stl", "/elsewhere", {}).path, root_ + "/urdf/m.stl");
  EXPECT_EQ(resolve_resource(root_ + "/urdf/m.stl", "/elsewhere", {}).path, root_ + "/urdf/m.stl");
  EXPECT_TRUE(resolve_resource("http://example.com/m.stl", root_, {}).path.empty());
  EXPECT_TRUE(resolve_resource("urdf", root_, {}).path.empty());  // a directory is no file
}

TEST(RosPackagePath, IsSplitAtColonsWithoutEmptyEntries) {
  const char* previous = std::getenv("ROS_PACKAGE_PATH");
  const std::string saved = previous ? previous : "";
  setenv("ROS_PACKAGE_PATH", "/a::/b/c:", 1);
  EXPECT_EQ(ros_package_path_directories(), (std::vector<std::string>{"/a", "/b/c"}));
  unsetenv("ROS_PACKAGE_PATH");
  EXPECT_TRUE(ros_package_path_directories().empty());
  if (previous) setenv("ROS_PACKAGE_PATH", saved.c_str(), 1);
}

}  // namespace
}  // namespace grpvss::io

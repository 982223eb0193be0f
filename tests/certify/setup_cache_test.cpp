// The set-up cache (certify::SetupCache) as RobotCell's offset source: a warm entry gives the
// same cell as building it; corrupt, truncated, stale and wrong-format entries are rebuilt with
// a note; a well-formed entry whose offset no longer contains the ball is rejected by the
// exact re-check (proofs/offset-containment.md#lemma-cached-offset) and overwritten.
#include "grpvss/certify/setup_cache.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "grpvss/certify/robot_cell.hpp"
#include "grpvss/exact/minkowski_offset.hpp"
#include "grpvss/io/environment_file.hpp"
#include "grpvss/io/robot_file.hpp"
#include "grpvss/report/input_digests.hpp"
#include "support/data_paths.hpp"
#include "support/text_files.hpp"

namespace {

using grpvss::certify::LinkOffsetInputs;
using grpvss::certify::RobotCell;
using grpvss::certify::SetupCache;
using grpvss::certify::SetupCacheOptions;
using Offsets = std::vector<std::vector<Eigen::Vector3d>>;

using grpvss::test::kIbm7545Data;

grpvss::certify::CellSettings thesis_settings() {
  grpvss::certify::CellSettings settings;
  settings.tolerance = 0.5;
  settings.offset_shape = grpvss::geometry::OffsetShape::kRhombicuboctahedron;
  return settings;
}

Offsets offsets_of(const RobotCell& cell) {
  Offsets offsets;
  for (const auto& hull : cell.hulls()) offsets.push_back(hull.expanded_L);
  return offsets;
}

// Face loops rotated to start at their smallest index, sorted: from_points gives the same
// faces in an order that may differ between two calls on the same points.
std::vector<std::vector<int>> canonical_faces(const grpvss::geometry::ConvexPolytope& p) {
  std::vector<std::vector<int>> faces = p.faces();
  for (auto& loop : faces) {
    std::rotate(loop.begin(), std::min_element(loop.begin(), loop.end()), loop.end());
  }
  std::sort(faces.begin(), faces.end());
  return faces;
}

// Bit-for-bit equality of what a cell derives from its offsets (== on doubles: same values).
void expect_same_cell(const RobotCell& expected, const RobotCell& actual) {
  ASSERT_EQ(expected.hulls().size(), actual.hulls().size());
  EXPECT_EQ(offsets_of(expected), offsets_of(actual));
  for (std::size_t i = 0; i < expected.hulls().size(); ++i) {
    EXPECT_EQ(canonical_faces(expected.expanded_polytope_L(i)),
              canonical_faces(actual.expanded_polytope_L(i)));
    EXPECT_EQ(expected.hulls()[i].expanded_sphere_L.center,
              actual.hulls()[i].expanded_sphere_L.center);
    EXPECT_EQ(expected.hulls()[i].expanded_sphere_L.radius_upper,
              actual.hulls()[i].expanded_sphere_L.radius_upper);
  }
  EXPECT_EQ(expected.expansion_radius(), actual.expansion_radius());
}

class SetupCacheTest : public ::testing::Test {
 protected:
  void SetUp() override {
    directory_ = grpvss::test::make_temporary_directory("setup-cache");
    robot_ = grpvss::io::read_robot_file(kIbm7545Data + "robot.txt");
    environment_ = grpvss::io::read_environment_file(kIbm7545Data + "environment.txt");
    reference_.emplace(robot_, environment_, thesis_settings());
  }
  void TearDown() override { std::filesystem::remove_all(directory_); }

  SetupCacheOptions options(const std::string& identity = "test build 1") const {
    return {directory_ + "/cache", identity};
  }
  LinkOffsetInputs inputs() const {
    return {reference_->hulls(), reference_->tolerance(), reference_->expansion_radius(),
            reference_->offset_shape()};
  }
  // A cell built through a fresh cache object (a new process, as far as the cache knows).
  RobotCell cell_through(SetupCache& cache) const {
    return RobotCell(robot_, environment_, thesis_settings(), &cache);
  }
  std::string entry_path() const { return SetupCache(options()).entry_path(inputs()); }
  // Writes `offsets` as a well-formed, current entry (checksum and key right).
  void write_entry(const Offsets& offsets, const std::string& identity = "test build 1") const {
    SetupCache writer(options(identity));
    ASSERT_FALSE(writer.propose(inputs()).has_value());
    writer.adopted(inputs(), offsets, 0);
  }
  // The next cell reads the entry, rejects it with a note containing `expected_note`, builds
  // the reference cell, and leaves an entry that the cell after it reads without a note.
  void expect_rebuilt_with_note(const std::string& expected_note) const {
    SetupCache cache(options());
    const RobotCell cell = cell_through(cache);
    expect_same_cell(*reference_, cell);
    ASSERT_EQ(cache.notes().size(), 1u);
    EXPECT_NE(cache.notes()[0].find(expected_note), std::string::npos) << cache.notes()[0];
    EXPECT_EQ(cache.notes()[0].rfind("set-up cache: ", 0), 0u);
    SetupCache after(options());
    expect_same_cell(*reference_, cell_through(after));
    EXPECT_TRUE(after.loaded());
    EXPECT_TRUE(after.notes().empty());
  }

  std::string directory_;
  grpvss::RobotModel robot_;
  grpvss::Environment environment_;
  std::optional<RobotCell> reference_;
};

TEST_F(SetupCacheTest, AWarmEntryGivesTheCellThatBuildingGives) {
  SetupCache cold(options());
  expect_same_cell(*reference_, cell_through(cold));
  EXPECT_FALSE(cold.loaded());
  EXPECT_TRUE(cold.notes().empty());
  ASSERT_TRUE(std::filesystem::exists(entry_path()));

  SetupCache warm(options());
  expect_same_cell(*reference_, cell_through(warm));
  EXPECT_TRUE(warm.loaded());
  EXPECT_TRUE(warm.notes().empty());
  // One entry, no temporary files left behind.
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(directory_ + "/cache"),
                          std::filesystem::directory_iterator()),
            1);
}

TEST_F(SetupCacheTest, TheKeyChangesWithTheToleranceTheShapeAndTheBuild) {
  const std::string path = entry_path();
  LinkOffsetInputs other_radius = inputs();
  other_radius.expansion_radius = std::nextafter(other_radius.expansion_radius, 1.0);
  LinkOffsetInputs other_shape = inputs();
  other_shape.offset_shape = grpvss::geometry::OffsetShape::kCube;
  LinkOffsetInputs other_tolerance = inputs();
  other_tolerance.tolerance = 0.25;
  EXPECT_NE(SetupCache(options()).entry_path(other_radius), path);
  EXPECT_NE(SetupCache(options()).entry_path(other_shape), path);
  EXPECT_NE(SetupCache(options()).entry_path(other_tolerance), path);
  EXPECT_NE(SetupCache(options("test build 2")).entry_path(inputs()), path);
  // A raw hull vertex one ulp away is another robot.
  std::vector<grpvss::certify::LinkHull> moved = reference_->hulls();
  moved[3].raw_L[0].x() = std::nextafter(moved[3].raw_L[0].x(), 100.0);
  const LinkOffsetInputs other_robot{moved, inputs().tolerance, inputs().expansion_radius,
                                     inputs().offset_shape};
  EXPECT_NE(SetupCache(options()).entry_path(other_robot), path);
}

TEST_F(SetupCacheTest, AFlippedByteIsCorruptAndRebuilt) {
  write_entry(offsets_of(*reference_));
  std::string text = grpvss::test::read_text_file(entry_path());
  const std::size_t at = text.find("offset ") + 20;  // inside the first coordinates
  text[at] = text[at] == '1' ? '2' : '1';
  std::ofstream(entry_path(), std::ios::binary | std::ios::trunc) << text;
  expect_rebuilt_with_note("is corrupt (bad checksum); rebuilt");
}

TEST_F(SetupCacheTest, ATruncatedEntryIsCorruptAndRebuilt) {
  write_entry(offsets_of(*reference_));
  const std::string text = grpvss::test::read_text_file(entry_path());
  std::ofstream(entry_path(), std::ios::binary | std::ios::trunc) << text.substr(0, text.size() / 2);
  expect_rebuilt_with_note("is corrupt (truncated); rebuilt");
}

TEST_F(SetupCacheTest, AnEntryOfAnotherBuildIsStaleAndRebuilt) {
  // Written by "another version" for the same inputs, then found under this build's name.
  write_entry(offsets_of(*reference_), "test build 0");
  const std::string other = SetupCache(options("test build 0")).entry_path(inputs());
  ASSERT_NE(other, entry_path());
  std::filesystem::rename(other, entry_path());
  expect_rebuilt_with_note("is stale (other inputs or another build); rebuilt");
}

TEST_F(SetupCacheTest, AnEntryOfAnotherFormatIsCorruptAndRebuilt) {
  // A file with a correct checksum in a format this build does not know.
  write_entry(offsets_of(*reference_));
  std::string text = grpvss::test::read_text_file(entry_path());
  text.replace(0, std::string("grpvss-setup-cache 1").size(), "grpvss-setup-cache 2");
  const std::string body = text.substr(0, text.rfind("checksum "));
  std::ofstream(entry_path(), std::ios::binary | std::ios::trunc)
      << body << "checksum " << grpvss::report::sha256_hex(body) << "\n";
  expect_rebuilt_with_note("is corrupt (wrong format); rebuilt");
}

// The soundness test: the entry is well formed and current (checksum and key right), but hull
// 3's offset is the one for 0.9 times the expansion radius, so it does not contain
// H (+) B(0, expansion_radius). Only the exact re-check can tell; without it the cell would
// use the smaller offset.
TEST_F(SetupCacheTest, AWellFormedEntryWhoseOffsetMissesTheBallIsRejected) {
  const double radius = reference_->expansion_radius();
  const auto raw = grpvss::geometry::ConvexPolytope::from_points(reference_->hulls()[3].raw_L);
  Offsets tampered = offsets_of(*reference_);
  tampered[3] = grpvss::geometry::minkowski_offset(raw, 0.9 * radius, reference_->offset_shape())
                    .vertices();
  // Independent of the library's check: some point h + r u of H (+) B(0, r) lies outside the
  // tampered offset's hull, seen along u = the axis directions (rhombicuboctahedron faces).
  bool escapes = false;
  for (int axis = 0; axis < 3; ++axis) {
    double raw_max = -1e300, tampered_max = -1e300;
    for (const auto& h : reference_->hulls()[3].raw_L) raw_max = std::max(raw_max, h[axis]);
    for (const auto& v : tampered[3]) tampered_max = std::max(tampered_max, v[axis]);
    escapes = escapes || raw_max + radius > tampered_max;
  }
  ASSERT_TRUE(escapes);
  write_entry(tampered);
  expect_rebuilt_with_note("failed the exact re-check (1 of 11 offsets); rebuilt");
}

// Points that are not all vertices (an interior point appended) are not an offset vertex list.
TEST_F(SetupCacheTest, AnOffsetWithAnInteriorPointIsRejected) {
  Offsets padded = offsets_of(*reference_);
  padded[0].push_back(reference_->hulls()[0].raw_L[0]);  // inside H (+) B(0, r)
  write_entry(padded);
  expect_rebuilt_with_note("failed the exact re-check (1 of 11 offsets); rebuilt");
}

TEST_F(SetupCacheTest, AnEntryWithTooFewOffsetsIsRejected) {
  Offsets fewer = offsets_of(*reference_);
  fewer.pop_back();
  write_entry(fewer);
  expect_rebuilt_with_note("failed the exact re-check (11 of 11 offsets); rebuilt");
}

TEST_F(SetupCacheTest, ADirectoryThatCannotBeCreatedIsANoteNotAFailure) {
  std::ofstream(directory_ + "/file") << "not a directory\n";
  SetupCache cache({directory_ + "/file/cache", "test build 1"});
  expect_same_cell(*reference_, cell_through(cache));
  ASSERT_EQ(cache.notes().size(), 1u);
  EXPECT_NE(cache.notes()[0].find("cannot use the directory " + directory_ + "/file/cache"),
            std::string::npos)
      << cache.notes()[0];
}

TEST(SetupCacheDirectory, FollowsXdgCacheHomeThenHome) {
  using grpvss::certify::default_setup_cache_directory;
  EXPECT_EQ(default_setup_cache_directory("/x/cache", "/home/u"), "/x/cache/grpvss");
  // A relative XDG_CACHE_HOME is invalid (XDG Base Directory) and ignored.
  EXPECT_EQ(default_setup_cache_directory("relative", "/home/u"), "/home/u/.cache/grpvss");
  EXPECT_EQ(default_setup_cache_directory("", "/home/u"), "/home/u/.cache/grpvss");
  EXPECT_EQ(default_setup_cache_directory(nullptr, "/home/u"), "/home/u/.cache/grpvss");
  EXPECT_EQ(default_setup_cache_directory(nullptr, nullptr), std::nullopt);
  EXPECT_EQ(default_setup_cache_directory(nullptr, ""), std::nullopt);
}

}  // namespace

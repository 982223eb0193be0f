#include "io/did_you_mean.hpp"

#include <string>
#include <vector>

#include <gtest/gtest.h>

namespace grpvss::io {
namespace {

TEST(DidYouMean, EditDistanceCountsInsertionsDeletionsAndSubstitutions) {
  EXPECT_EQ(edit_distance("", ""), 0u);
  EXPECT_EQ(edit_distance("abc", ""), 3u);
  EXPECT_EQ(edit_distance("", "ab"), 2u);
  EXPECT_EQ(edit_distance("kitten", "sitting"), 3u);  // k->s, e->i, +g
  EXPECT_EQ(edit_distance("obstacle", "obstacles"), 1u);
  EXPECT_EQ(edit_distance("lenght", "length"), 2u);  // a transposition is two edits
  EXPECT_EQ(edit_distance("flaw", "lawn"), 2u);
}

TEST(DidYouMean, SuggestsOnlyCloseCandidates) {
  const std::vector<std::string_view> keys{"units", "robot", "obstacles", "tolerance"};
  EXPECT_EQ(closest_candidate("obstacle", keys), "obstacles");
  EXPECT_EQ(closest_candidate("tolerence", keys), "tolerance");
  EXPECT_EQ(closest_candidate("robots", keys), "robot");
  EXPECT_EQ(closest_candidate("speed", keys), "");  // far from every key
  EXPECT_EQ(closest_candidate("ab", {"a", "b"}), "");  // distance 1 is half of a 2-letter word
  EXPECT_EQ(did_you_mean("unit", keys), " (did you mean 'units'?)");
  EXPECT_EQ(did_you_mean("xyz", keys), "");
  EXPECT_EQ(closest_candidate(std::string(100, 'a'), {std::string_view("a")}), "");
}

}  // namespace
}  // namespace grpvss::io

// Streamed JSON arrays (report/streamed_json.hpp) against nlohmann's dump of the whole document:
// the same bytes, pretty and compact, nested, empty, and with a lookalike of the placeholder
// inside a string.
#include "grpvss/report/streamed_json.hpp"

#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

namespace grpvss::report {
namespace {

using nlohmann::json;

/// `document` with members "a" and "b.c" replaced by streamed arrays of `a` and `c`.
std::string streamed(json document, const std::vector<json>& a, const std::vector<json>& c,
                     int indent) {
  document["a"] = streamed_array_placeholder(0);
  document["b"]["c"] = streamed_array_placeholder(1);
  const TemplateCut cut = cut_at_placeholders(document.dump(indent), 2, indent);
  std::string text;
  for (std::size_t i = 0; i < cut.placeholders.size(); ++i) {
    text += cut.pieces[i];
    JsonArrayText array(indent, cut.pads[i]);
    for (const json& element : cut.placeholders[i] == 0 ? a : c) {
      text += array.next_element();
      text += array.dump_element(element);
    }
    text += array.close();
  }
  return text + cut.pieces.back();
}

json sample_document() {
  return {{"z", 1},
          {"name", "x: \"@grpvss-streamed-array-0@\" and \"@grpvss-streamed-array-1@\""},
          {"b", {{"before", {1, 2}}, {"empty", json::object()}, {"d", "after"}}},
          {"m", json::array()}};
}

std::vector<json> elements_a() {
  return {{{"k", 1}, {"v", {1.5, -2.25e-9, nullptr}}, {"s", "line\nbreak"}},
          json::array({json::array(), json::object(), {{"x", json::array({1})}}}),
          7,
          "text"};
}

std::vector<json> elements_c() {
  return {{{"deep", {{"deeper", {1, 2, 3}}}}}, json::object()};
}

TEST(StreamedJson, PrettyArraysGiveTheBytesOfTheWholeDump) {
  for (int indent : {1, 2, 4}) {
    json whole = sample_document();
    whole["a"] = elements_a();
    whole["b"]["c"] = elements_c();
    EXPECT_EQ(streamed(sample_document(), elements_a(), elements_c(), indent), whole.dump(indent))
        << "indent " << indent;
  }
}

TEST(StreamedJson, CompactArraysGiveTheBytesOfTheWholeDump) {
  json whole = sample_document();
  whole["a"] = elements_a();
  whole["b"]["c"] = elements_c();
  EXPECT_EQ(streamed(sample_document(), elements_a(), elements_c(), -1), whole.dump());
}

TEST(StreamedJson, EmptyArraysAreWrittenAsTheDumpWritesThem) {
  for (int indent : {-1, 0, 2}) {
    json whole = sample_document();
    whole["a"] = json::array();
    whole["b"]["c"] = json::array();
    EXPECT_EQ(streamed(sample_document(), {}, {}, indent), whole.dump(indent)) << indent;
  }
}

TEST(StreamedJson, APlaceholderInsideAStringIsNotCut) {
  // sample_document's "name" holds both placeholders quoted: only the values are cut.
  json document = sample_document();
  document["a"] = streamed_array_placeholder(0);
  document["b"]["c"] = streamed_array_placeholder(1);
  const TemplateCut cut = cut_at_placeholders(document.dump(2), 2, 2);
  ASSERT_EQ(cut.pieces.size(), 3u);
  EXPECT_EQ(cut.placeholders, (std::vector<int>{0, 1}));
  EXPECT_EQ(cut.pads, (std::vector<int>{2, 4}));  // "a": a member; "c": a member of "b"
  EXPECT_NE(cut.pieces[2].find("@grpvss-streamed-array-0@"), std::string::npos);  // "name"
  EXPECT_NE(cut.pieces[2].find("@grpvss-streamed-array-1@"), std::string::npos);
}

TEST(StreamedJson, AMissingOrRepeatedPlaceholderIsALogicError) {
  const json missing = {{"a", 1}};
  EXPECT_THROW(cut_at_placeholders(missing.dump(2), 1, 2), std::logic_error);
  const json repeated = {{"a", streamed_array_placeholder(0)}, {"b", streamed_array_placeholder(0)}};
  EXPECT_THROW(cut_at_placeholders(repeated.dump(2), 1, 2), std::logic_error);
}

}  // namespace
}  // namespace grpvss::report

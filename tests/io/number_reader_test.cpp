#include "io/number_reader.hpp"

#include <string>

#include <gtest/gtest.h>

#include "support/input_error_expectations.hpp"

namespace grpvss::io {
namespace {

using grpvss::testing::expect_input_error;

TEST(NumberReader, SplitsOnCommasAndBlanksAndAllowsATrailingComma) {
  NumberReader reader("1, 2\t3,\n", "t.txt");
  const NumberLine row = reader.read_numbers(3, "a row");
  EXPECT_EQ(row.line, 1);
  EXPECT_EQ(row.values, (std::vector<double>{1.0, 2.0, 3.0}));
  EXPECT_TRUE(reader.at_end());
}

TEST(NumberReader, SkipsBlankAndCommentLinesButCountsThem) {
  NumberReader reader("\n# a comment\n   \r\n5 # five\n\n", "t.txt");
  EXPECT_EQ(reader.read_number("a value"), 5.0);
  EXPECT_EQ(reader.line(), 4);
  EXPECT_TRUE(reader.at_end());
  EXPECT_NO_THROW(reader.expect_end("the value"));
}

TEST(NumberReader, ReadsFortranStyleNumbersExactlyAsFromChars) {
  NumberReader reader("2., .5, +3, -1e2, 1E-3, 0.1\r\n", "t.txt");
  const NumberLine row = reader.read_numbers(6, "a row");
  EXPECT_EQ(row.values, (std::vector<double>{2.0, 0.5, 3.0, -100.0, 1e-3, 0.1}));
}

TEST(NumberReader, IgnoresAByteOrderMarkOnlyAtTheStart) {
  NumberReader reader("\xEF\xBB\xBF" "4\n", "t.txt");
  EXPECT_EQ(reader.read_integer("a count", 0, 9), 4);
  expect_input_error(
      [] {
        NumberReader later("1\n\xEF\xBB\xBF" "4\n", "t.txt");
        later.read_number("a value");
        later.read_number("a value");
      },
      "t.txt", 2, "t.txt:2: expected a number for a value, found '\\xef\\xbb\\xbf4'");
}

TEST(NumberReader, AcceptsMagnitudeUpToOneBillion) {
  NumberReader reader("1e9, -1000000000", "t.txt");
  EXPECT_EQ(reader.read_numbers(2, "a row").values, (std::vector<double>{1e9, -1e9}));
}

TEST(NumberReader, RejectsANonNumber) {
  expect_input_error([] { NumberReader("\n1, abc, 3\n", "t.txt").read_numbers(3, "a row"); },
                     "t.txt", 2, "t.txt:2: expected a number for a row, found 'abc'");
}

TEST(NumberReader, RejectsAnEmptyFieldBetweenCommas) {
  expect_input_error([] { NumberReader("1,,2\n", "t.txt").read_numbers(2, "a row"); }, "t.txt",
                     1, "t.txt:1: expected a number for a row, found an empty field");
}

TEST(NumberReader, RejectsALeadingComma) {
  expect_input_error([] { NumberReader(",1,2\n", "t.txt").read_numbers(2, "a row"); }, "t.txt",
                     1, "t.txt:1: expected a number for a row, found an empty field");
}

TEST(NumberReader, RejectsNotANumber) {
  expect_input_error([] { NumberReader("1, nan, 3\n", "t.txt").read_numbers(3, "a row"); },
                     "t.txt", 1, "t.txt:1: expected a finite number for a row, found 'nan'");
}

TEST(NumberReader, RejectsInfinity) {
  expect_input_error([] { NumberReader("-inf\n", "t.txt").read_number("a value"); }, "t.txt", 1,
                     "t.txt:1: expected a finite number for a value, found '-inf'");
}

TEST(NumberReader, RejectsGiganticMagnitude) {
  expect_input_error(
      [] { NumberReader("1.0000001e9\n", "t.txt").read_number("a value"); }, "t.txt", 1,
      "t.txt:1: expected a number of magnitude at most 1e9 for a value, found '1.0000001e9'");
}

TEST(NumberReader, RejectsOverflowingLiteral) {
  expect_input_error([] { NumberReader("1e400\n", "t.txt").read_number("a value"); }, "t.txt",
                     1, "t.txt:1: expected a number of magnitude at most 1e9 for a value, found '1e400'");
}

TEST(NumberReader, RejectsHexadecimalAndTrailingCharacters) {
  expect_input_error([] { NumberReader("0x10\n", "t.txt").read_number("a value"); }, "t.txt", 1,
                     "t.txt:1: expected a number for a value, found '0x10'");
  expect_input_error([] { NumberReader("3.5in\n", "t.txt").read_number("a value"); }, "t.txt", 1,
                     "t.txt:1: expected a number for a value, found '3.5in'");
}

TEST(NumberReader, QuotesAtMostFortyCharactersOfAField) {
  const std::string field(50, 'x');
  expect_input_error([&] { NumberReader(field, "t.txt").read_number("a value"); }, "t.txt", 1,
                     "t.txt:1: expected a number for a value, found '" + std::string(40, 'x') +
                         "...'");
}

TEST(NumberReader, EscapesUnprintableBytesInMessages) {
  expect_input_error(
      [] { NumberReader(std::string("1\0x\x7f\xc3\xa9", 6), "t.txt").read_number("a value"); },
      "t.txt", 1, "t.txt:1: expected a number for a value, found '1\\x00x\\x7f\\xc3\\xa9'");
}

TEST(NumberReader, RejectsAnOverLongLine) {
  std::string line = "1";
  line.append(4096, ' ');  // 4097 characters
  expect_input_error([&] { NumberReader(line + "\n", "t.txt").at_end(); }, "t.txt", 1,
                     "t.txt:1: expected a line of at most 4096 characters, found 4097 characters");
  // at_end() looks past the consumed line 1 and meets line 2.
  expect_input_error(
      [&] {
        const std::string text = "2\n" + line + "\n";  // the reader keeps a view of it
        NumberReader reader(text, "t.txt");
        reader.read_number("a value");
        reader.at_end();
      },
      "t.txt", 2, "t.txt:2: expected a line of at most 4096 characters, found 4097 characters");
}

TEST(NumberReader, AcceptsALineOfExactly4096Characters) {
  std::string line = "1";
  line.append(4095, ' ');
  NumberReader reader(line, "t.txt");
  EXPECT_EQ(reader.read_number("a value"), 1.0);
}

TEST(NumberReader, ReportsAWrongCountOfNumbers) {
  expect_input_error([] { NumberReader("1 2\n", "t.txt").read_numbers(3, "a point"); }, "t.txt",
                     1, "t.txt:1: expected 3 numbers for a point, found 2 numbers");
  expect_input_error([] { NumberReader("1 2\n", "t.txt").read_number("a value"); }, "t.txt", 1,
                     "t.txt:1: expected 1 number for a value, found 2 numbers");
}

TEST(NumberReader, ReportsEndOfFileOnTheLineAfterTheLast) {
  expect_input_error(
      [] {
        NumberReader reader("1\n2\n", "t.txt");
        reader.read_number("a value");
        reader.read_number("a value");
        reader.read_numbers(3, "a point");
      },
      "t.txt", 3, "t.txt:3: expected 3 numbers for a point, found end of file");
  // Without a final newline the last line still counts once.
  expect_input_error(
      [] {
        NumberReader reader("1\n2", "t.txt");
        reader.read_number("a value");
        reader.read_number("a value");
        reader.read_number("the third value");
      },
      "t.txt", 3, "t.txt:3: expected 1 number for the third value, found end of file");
}

TEST(NumberReader, ReadsIntegersStrictly) {
  NumberReader reader("+4\n-2\n", "t.txt");
  EXPECT_EQ(reader.read_integer("a count", 0, 10), 4);
  EXPECT_EQ(reader.read_integer("an offset", -5, 5), -2);
  expect_input_error([] { NumberReader("2.\n", "t.txt").read_integer("a count", 0, 9); },
                     "t.txt", 1, "t.txt:1: expected an integer for a count, found '2.'");
  expect_input_error([] { NumberReader("2.5\n", "t.txt").read_integer("a count", 0, 9); },
                     "t.txt", 1, "t.txt:1: expected an integer for a count, found '2.5'");
  expect_input_error(
      [] { NumberReader("99999999999999999999\n", "t.txt").read_integer("a count", 0, 9); },
      "t.txt", 1, "t.txt:1: expected an integer for a count, found '99999999999999999999'");
}

TEST(NumberReader, ChecksTheIntegerRange) {
  expect_input_error([] { NumberReader("10\n", "t.txt").read_integer("a count", 1, 9); },
                     "t.txt", 1, "t.txt:1: expected a count between 1 and 9, found 10");
  expect_input_error([] { NumberReader("1 2\n", "t.txt").read_integer("a count", 1, 9); },
                     "t.txt", 1, "t.txt:1: expected a single integer for a count, found 2 fields");
}

TEST(NumberReader, ReadsAKeywordLineOnlyWhenItIsThere) {
  NumberReader reader("1, 2, 3\nhull 8\n", "t.txt");
  EXPECT_EQ(reader.read_keyword_integer("HULL", "a size", 4, 10), std::nullopt);
  EXPECT_EQ(reader.read_numbers(3, "a point").line, 1);
  EXPECT_EQ(reader.read_keyword_integer("HULL", "a size", 4, 10), 8);
  EXPECT_EQ(reader.line(), 2);
  EXPECT_TRUE(reader.at_end());
}

TEST(NumberReader, RejectsAMalformedKeywordLine) {
  expect_input_error(
      [] { NumberReader("HULL\n", "t.txt").read_keyword_integer("HULL", "a size", 4, 10); },
      "t.txt", 1, "t.txt:1: expected 'HULL k' with one integer k for a size, found 1 field");
  expect_input_error(
      [] { NumberReader("HULL 3\n", "t.txt").read_keyword_integer("HULL", "a size", 4, 10); },
      "t.txt", 1, "t.txt:1: expected a size between 4 and 10, found 3");
}

TEST(NumberReader, RejectsTrailingGarbage) {
  expect_input_error(
      [] {
        NumberReader reader("1\n\n2 3\n", "t.txt");
        reader.read_number("a value");
        reader.expect_end("the value");
      },
      "t.txt", 3, "t.txt:3: expected end of file after the value, found '2'");
}

}  // namespace
}  // namespace grpvss::io

/// The tokenizer and cursor shared by the robot-program readers.

#include "grpvss/io/program_lexer.hpp"

#include <memory>
#include <string>

#include <gtest/gtest.h>

#include "support/input_error_expectations.hpp"

namespace grpvss::io {
namespace {

using grpvss::testing::expect_input_error;

struct Expected {
  TokenKind kind;
  std::string text;
  int line;
};

void expect_tokens(const std::vector<ProgramToken>& tokens, const std::vector<Expected>& expected) {
  ASSERT_EQ(tokens.size(), expected.size());
  for (std::size_t i = 0; i < tokens.size(); ++i) {
    EXPECT_EQ(tokens[i].kind, expected[i].kind) << "token " << i;
    EXPECT_EQ(tokens[i].text, expected[i].text) << "token " << i;
    EXPECT_EQ(tokens[i].line, expected[i].line) << "token " << i;
  }
}

constexpr TokenKind kName = TokenKind::kName;
constexpr TokenKind kNumber = TokenKind::kNumber;
constexpr TokenKind kString = TokenKind::kString;
constexpr TokenKind kSymbol = TokenKind::kSymbol;
constexpr TokenKind kEnd = TokenKind::kEndOfLine;

TEST(ProgramLexer, UrScriptDropsCommentsAndStepLabels) {
  const std::string text = "movel(p[0.1, -2e-3], a=1.2) # go\n  $ 1 \"Robot Program\"\n\nx = 'it''s'\n";
  const auto tokens = tokenize_program(text, "a.script", ProgramDialect::kUrScript);
  expect_tokens(tokens, {{kName, "movel", 1}, {kSymbol, "(", 1}, {kName, "p", 1}, {kSymbol, "[", 1},
                         {kNumber, "0.1", 1}, {kSymbol, ",", 1}, {kSymbol, "-", 1}, {kNumber, "2e-3", 1},
                         {kSymbol, "]", 1}, {kSymbol, ",", 1}, {kName, "a", 1}, {kSymbol, "=", 1},
                         {kNumber, "1.2", 1}, {kSymbol, ")", 1}, {kEnd, "", 1}, {kName, "x", 4},
                         {kSymbol, "=", 4}, {kString, "it", 4}, {kString, "s", 4}, {kEnd, "", 4}});
  EXPECT_EQ(tokens[4].number, 0.1);
  EXPECT_EQ(tokens[7].number, 2e-3);
}

TEST(ProgramLexer, KrlReadsSystemVariablesEnumsAndBitLiterals) {
  const std::string text =
      "&ACCESS RVP\n;FOLD PTP P1\nPTP XP1 ; to P1\n$VEL.CP=0.2\nBAS(#INITMOV,0)\nS 'B010' T 'h1F'\n";
  const auto tokens = tokenize_program(text, "a.src", ProgramDialect::kKrl);
  expect_tokens(tokens, {{kName, "PTP", 3}, {kName, "XP1", 3}, {kEnd, "", 3}, {kName, "$VEL", 4},
                         {kSymbol, ".", 4}, {kName, "CP", 4}, {kSymbol, "=", 4}, {kNumber, "0.2", 4},
                         {kEnd, "", 4}, {kName, "BAS", 5}, {kSymbol, "(", 5}, {kName, "#INITMOV", 5},
                         {kSymbol, ",", 5}, {kNumber, "0", 5}, {kSymbol, ")", 5}, {kEnd, "", 5},
                         {kName, "S", 6}, {kNumber, "'B010'", 6}, {kName, "T", 6}, {kNumber, "'h1F'", 6},
                         {kEnd, "", 6}});
  EXPECT_EQ(tokens[17].number, 2.0);
  EXPECT_EQ(tokens[19].number, 31.0);
}

TEST(ProgramLexer, RapidSkipsTheHeaderAndKeepsDoubledQuotes) {
  const std::string text =
      "%%%\n  VERSION:1\n%%%\nMODULE m ! main\n  s := \"say \"\"hi\"\"\";\n  x := 9E+09;\n";
  const auto tokens = tokenize_program(text, "a.mod", ProgramDialect::kRapid);
  expect_tokens(tokens, {{kName, "MODULE", 4}, {kName, "m", 4}, {kEnd, "", 4}, {kName, "s", 5},
                         {kSymbol, ":=", 5}, {kString, "say \"\"hi\"\"", 5}, {kSymbol, ";", 5},
                         {kEnd, "", 5}, {kName, "x", 6}, {kSymbol, ":=", 6}, {kNumber, "9E+09", 6},
                         {kSymbol, ";", 6}, {kEnd, "", 6}});
  EXPECT_EQ(tokens[10].number, 9e9);
}

TEST(ProgramLexer, ReportsMalformedTokensWithFileAndLine) {
  const auto lex = [](const std::string& text, ProgramDialect dialect) {
    return [=] { tokenize_program(text, "f", dialect); };
  };
  expect_input_error(lex("x = 1\ntextmsg(\"open\n", ProgramDialect::kUrScript), "f", 2,
                     "f:2: expected the closing \" of a string, found end of line");
  expect_input_error(lex("a = 1.2.3\n", ProgramDialect::kUrScript), "f", 1,
                     "f:1: expected a number, found '1.2.3'");
  expect_input_error(lex("\n\nq = 12abc\n", ProgramDialect::kUrScript), "f", 3,
                     "f:3: expected a number, found '12abc'");
  expect_input_error(lex("PTP\n x = \x01\n", ProgramDialect::kKrl), "f", 2,
                     "f:2: expected a program character, found '\\x01'");
  expect_input_error(lex("T 'B012'\n", ProgramDialect::kKrl), "f", 1,
                     "f:1: expected a bit ('B0101') or hex ('H1F') literal of at most 31 bits, found ''B012''");
  // Found by fuzz/krl_fuzzer: a quote as the text's last byte was read past the end.
  expect_input_error(lex("ENDDAT'", ProgramDialect::kKrl), "f", 1,
                     "f:1: expected a bit ('B0101') or hex ('H1F') literal of at most 31 bits, found '''");
  expect_input_error(lex("S 'B", ProgramDialect::kKrl), "f", 1,
                     "f:1: expected a bit ('B0101') or hex ('H1F') literal of at most 31 bits, found ''B'");
  expect_input_error(lex("\n%%%\n VERSION:1\n", ProgramDialect::kRapid), "f", 2,
                     "f:2: expected a closing %%% line for the header opened here, found end of file");
  expect_input_error(lex("x := 1e999;\n", ProgramDialect::kRapid), "f", 1,
                     "f:1: expected a finite number, found '1e999'");
}

TEST(ProgramLexer, UrScriptStatementsContinueInsideBracketsKrlOnesDoNot) {
  const std::string text = "a = [1,\n  2]\nb = 3\n";
  const auto ur = tokenize_program(text, "f", ProgramDialect::kUrScript);
  const auto statements = split_line_statements(ur, "f");
  ASSERT_EQ(statements.size(), 2u);
  EXPECT_EQ(statements[0].line, 1);
  EXPECT_EQ(join_tokens(ur, statements[0].begin, statements[0].end), "a=[1, 2]");
  EXPECT_EQ(statements[1].line, 3);
  const auto krl = tokenize_program(text, "f", ProgramDialect::kKrl);
  expect_input_error([&] { split_line_statements(krl, "f"); }, "f", 1,
                     "f:1: expected a closing ']', found end of statement");
  const auto unmatched = tokenize_program("x = (1]\n", "f", ProgramDialect::kKrl);
  expect_input_error([&] { split_line_statements(unmatched, "f"); }, "f", 1,
                     "f:1: expected ')', found ']'");
}

TEST(ProgramLexer, CursorNamesWhatWasExpected) {
  const auto tokens = tokenize_program("PTP XP1 C_DIS\n", "f", ProgramDialect::kKrl);
  TokenCursor cursor(tokens, split_line_statements(tokens, "f")[0], "f");
  EXPECT_TRUE(cursor.accept_name("ptp"));  // case-insensitive
  EXPECT_EQ(cursor.expect_name("a point").text, "XP1");
  expect_input_error([&] { cursor.expect_symbol(",", "','"); }, "f", 1, "f:1: expected ',', found 'C_DIS'");
  cursor.next("C_DIS");
  expect_input_error([&] { cursor.next("more"); }, "f", 1, "f:1: expected more, found end of statement");
  EXPECT_EQ(cursor.statement_text(), "PTP XP1 C_DIS");
}

TEST(ProgramLexer, NestingDeeperThanTheLimitIsRejected) {
  const std::string text(70, '(');
  const auto tokens = tokenize_program(text, "f", ProgramDialect::kUrScript);
  TokenCursor cursor(tokens, {0, tokens.size(), 1}, "f");
  std::vector<std::unique_ptr<TokenCursor::NestingGuard>> guards;
  for (int depth = 0; depth < TokenCursor::kMaxNesting; ++depth) {
    guards.push_back(std::make_unique<TokenCursor::NestingGuard>(cursor));
  }
  expect_input_error([&] { TokenCursor::NestingGuard too_deep(cursor); }, "f", 1,
                     "f:1: expected an expression nested at most 64 deep, found '('");
}

TEST(ProgramLexer, JoinsTokensAsWritten) {
  const auto join = [](const std::string& text, ProgramDialect dialect) {
    const auto tokens = tokenize_program(text, "f", dialect);
    return join_tokens(tokens, 0, tokens.size() - 1);
  };
  EXPECT_EQ(join("movel(p[0.1, -0.2, 3], a=1.2, v=0.25)\n", ProgramDialect::kUrScript),
            "movel(p[0.1, -0.2, 3], a=1.2, v=0.25)");
  EXPECT_EQ(join("MoveL RelTool(p, 0, 0, -100 \\Rz:=45), v500\\V:=650, z20, t;\n", ProgramDialect::kRapid),
            "MoveL RelTool(p, 0, 0, -100\\Rz:=45), v500\\V:=650, z20, t;");
  EXPECT_EQ(join("$VEL.CP = 2 - 1\n", ProgramDialect::kKrl), "$VEL.CP=2 - 1");
  EXPECT_EQ(line_after_text("a\nb\n"), 3);
  EXPECT_EQ(line_after_text("a\nb"), 3);
  EXPECT_EQ(line_after_text(""), 1);
}

}  // namespace
}  // namespace grpvss::io

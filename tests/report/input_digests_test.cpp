#include "grpvss/report/input_digests.hpp"

#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "grpvss/common/input_error.hpp"
#include "support/text_files.hpp"

namespace grpvss::report {
namespace {

// FIPS 180-2 test vectors (independent of OpenSSL).
constexpr const char* kEmpty = "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855";
constexpr const char* kAbc = "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad";
constexpr const char* kTwoBlocks =
    "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1";

TEST(InputDigests, Sha256OfFipsTestVectors) {
  EXPECT_EQ(sha256_hex(""), kEmpty);
  EXPECT_EQ(sha256_hex("abc"), kAbc);
  EXPECT_EQ(sha256_hex("abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq"), kTwoBlocks);
}

TEST(InputDigests, FileDigestEqualsDigestOfItsBytesAcrossReadChunks) {
  const std::string dir = test::make_temporary_directory("digest");
  std::string big(200000, '\0');  // > the 64 KiB read buffer: exercises several updates
  for (std::size_t i = 0; i < big.size(); ++i) big[i] = static_cast<char>((i * 131) % 251);
  std::ofstream(dir + "/big.bin", std::ios::binary) << big;
  std::ofstream(dir + "/abc.txt", std::ios::binary) << "abc";
  EXPECT_EQ(sha256_hex_of_file(dir + "/abc.txt"), kAbc);
  EXPECT_EQ(sha256_hex_of_file(dir + "/big.bin"), sha256_hex(big));
  std::filesystem::remove_all(dir);
}

TEST(InputDigests, DigestsNameTheFilesAsGiven) {
  const std::string dir = test::make_temporary_directory("digest");
  std::ofstream(dir + "/r.txt") << "abc";
  std::ofstream(dir + "/e.txt") << "";
  std::ofstream(dir + "/p.txt") << "abc";
  const InputDigests digests =
      digest_input_files(dir + "/r.txt", dir + "/e.txt", dir + "/p.txt");
  EXPECT_EQ(digests.robot.file, dir + "/r.txt");
  EXPECT_EQ(digests.robot.sha256, kAbc);
  EXPECT_EQ(digests.environment.file, dir + "/e.txt");
  EXPECT_EQ(digests.environment.sha256, kEmpty);
  EXPECT_EQ(digests.path.sha256, kAbc);
  std::filesystem::remove_all(dir);
}

TEST(InputDigests, MissingFileIsAnInputErrorNamingIt) {
  try {
    sha256_hex_of_file("/nonexistent/robot.txt");
    FAIL() << "no error for a missing file";
  } catch (const InputError& error) {
    EXPECT_EQ(error.file(), "/nonexistent/robot.txt");
    EXPECT_EQ(error.line(), 0);
    EXPECT_EQ(error.expected(), "a readable input file");
  }
}

}  // namespace
}  // namespace grpvss::report

// read_certificate_file (two callback passes, one segment built at a time) against
// certificate_from_json of the whole document: the same certificate from a real run, and the
// same InputError message for every malformed variant and every fuzz reproducer.
#include "grpvss/evidence/certificate_file.hpp"

#include <filesystem>
#include <functional>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "grpvss/certify/verifier.hpp"
#include "grpvss/common/input_error.hpp"
#include "grpvss/io/environment_file.hpp"
#include "grpvss/io/path_file.hpp"
#include "grpvss/io/robot_file.hpp"
#include "grpvss/motion/kinematics_adapter.hpp"
#include "support/data_paths.hpp"
#include "support/text_files.hpp"

namespace grpvss::certify {
namespace {

using nlohmann::json;

using grpvss::test::ibm7545_file;

/// The certificate of the sample path (COLLISION, several segments), with an "inputs" object
/// as verify writes it.
json sample_certificate() {
  const RobotModel robot = io::read_robot_file(ibm7545_file("robot.txt"));
  const Environment environment = io::read_environment_file(ibm7545_file("environment.txt"));
  const PathProgram program = io::read_path_file(ibm7545_file("path.txt"), robot);
  SetupRequest options;
  options.tolerance = 0.5;
  const VerificationRun run = verify(
      robot, environment, program,
      motion::make_kinematics_access(robot, motion::select_ik({}, robot, "robot.txt")), resolve_setup(options));
  json document = certificate_to_json(run.certificate);
  document["inputs"] = {{"robot", "r"}, {"ik", "ibm7545"}};
  return document;
}

/// What read_certificate_file delivers: the header's certificate with the segments appended,
/// its document, or the InputError message.
struct Streamed {
  Certificate certificate;
  json document;
  std::size_t announced = 0;
  std::string error;
};

Streamed read_streamed(const std::string& path) {
  Streamed out;
  try {
    read_certificate_file(
        path,
        [&](const CertificateFileHeader& header) {
          out.certificate = header.certificate;
          EXPECT_TRUE(out.certificate.segments.empty());
          out.document = header.document;
          out.announced = header.segment_count;
        },
        [&](const SegmentCertificate& segment) { out.certificate.segments.push_back(segment); });
  } catch (const InputError& error) {
    out.error = error.what();
  }
  return out;
}

/// The whole-document reader as check-certificate used it: parse, then certificate_from_json.
std::string whole_error(const std::string& path) {
  const std::string text = test::read_text_file(path);
  try {
    json document;
    try {
      document = json::parse(text);
    } catch (const json::exception& error) {
      throw InputError(path, 0, "a JSON document", error.what());
    }
    (void)certificate_from_json(document, path);
  } catch (const InputError& error) {
    return error.what();
  }
  return {};
}

class CertificateFile : public ::testing::Test {
 protected:
  void SetUp() override { directory_ = test::make_temporary_directory("certificate-file"); }
  void TearDown() override { std::filesystem::remove_all(directory_); }
  std::string write(const std::string& name, const std::string& text) {
    const std::string path = directory_ + "/" + name;
    std::ofstream(path, std::ios::binary) << text;
    return path;
  }
  std::string directory_;
};

TEST_F(CertificateFile, DeliversTheCertificateTheWholeDocumentHolds) {
  const json document = sample_certificate();
  const std::string path = write("c.json", document.dump(1) + "\n");
  const Streamed streamed = read_streamed(path);
  ASSERT_EQ(streamed.error, "");
  const Certificate whole = certificate_from_json(document, path);
  ASSERT_GE(whole.segments.size(), 2u);
  EXPECT_EQ(streamed.announced, whole.segments.size());
  // Compared through the writer: every field of every step.
  EXPECT_EQ(certificate_to_json(streamed.certificate), certificate_to_json(whole));
  EXPECT_EQ(streamed.document.at("inputs"), document.at("inputs"));
  EXPECT_EQ(streamed.document.at("segments"), json::array());  // never built in the header
}

TEST_F(CertificateFile, MalformedCertificatesGiveTheWholeDocumentReadersError) {
  const json good = sample_certificate();
  std::vector<std::pair<std::string, std::string>> variants;
  const auto with = [&](const std::string& name, const std::function<void(json&)>& change) {
    json document = good;
    change(document);
    variants.emplace_back(name, document.dump(1));
  };
  with("segments-object", [](json& d) { d["segments"] = {{"a", 1}}; });
  with("segments-number", [](json& d) { d["segments"] = 7; });
  with("segments-missing", [](json& d) { d.erase("segments"); });
  with("segment-primitive", [](json& d) { d["segments"][1] = 3; });
  with("segment-array", [](json& d) { d["segments"][1] = json::array({1, 2}); });
  with("segment-without-steps", [](json& d) { d["segments"][0].erase("steps"); });
  with("step-bad-q", [](json& d) { d["segments"][1]["steps"][0]["q"] = "x"; });
  with("bad-governing", [](json& d) {
    d["segments"][0]["steps"][0]["to_next"]["governing"][0] = "made-up";
  });
  with("tolerance-string", [](json& d) { d["tolerance"] = "0.5"; });
  with("no-version", [](json& d) { d.erase("version"); });
  with("bad-header-and-bad-segment", [](json& d) {
    d["cp_speed"] = 0;
    d["segments"][0] = 1;
  });
  variants.emplace_back("top-level-array", "[1, 2]");
  variants.emplace_back("truncated", good.dump(1).substr(0, 5000));
  variants.emplace_back("number-beyond-double", "{\"format\": \"grpvss-certificate\", \"x\": 1e9999}");
  variants.emplace_back("nested", std::string(100'000, '['));
  for (const auto& [name, text] : variants) {
    const std::string path = write(name + ".json", text);
    const std::string expected = whole_error(path);
    ASSERT_NE(expected, "") << name;
    EXPECT_EQ(read_streamed(path).error, expected) << name;
  }
}

TEST_F(CertificateFile, EveryFuzzReproducerEndsAsWithTheWholeDocumentReader) {
  int count = 0;
  for (const std::string kind : {"certificate", "certificate_checker"}) {
    const std::string directory = std::string(GRPVSS_SOURCE_DIR) + "/tests/regressions/" + kind;
    for (const auto& entry : std::filesystem::directory_iterator(directory)) {
      const std::string path = entry.path().string();
      const Streamed streamed = read_streamed(path);
      EXPECT_EQ(streamed.error, whole_error(path)) << path;
      ++count;
    }
  }
  EXPECT_GE(count, 5);
}

}  // namespace
}  // namespace grpvss::certify

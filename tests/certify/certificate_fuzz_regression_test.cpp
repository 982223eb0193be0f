// Regressions found with the certificate fuzz target (fuzz/, docs/reliability.md): by the
// fuzzer (a number beyond double range) or while writing it (the rest). Every reproducer under
// tests/regressions/certificate/ goes through the certificate fuzz target's harness and must
// end as the contract says (a Certificate or grpvss::InputError, nothing else); the specific
// defects are pinned by their exact messages.
#include <filesystem>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "grpvss/evidence/certificate.hpp"
#include "grpvss/common/input_error.hpp"
#include "support/text_files.hpp"

namespace {

const std::string kRegressions = std::string(GRPVSS_SOURCE_DIR) + "/tests/regressions/certificate";

/// The message certificate_from_json throws for `text`, or "" when it returns a certificate.
std::string parse_error_message(const std::string& text) {
  try {
    (void)grpvss::certify::certificate_from_json(nlohmann::json::parse(text), "c.json");
  } catch (const grpvss::InputError& error) {
    return error.what();
  }
  return {};
}

std::string reproducer(const std::string& name) {
  return grpvss::test::read_text_file(kRegressions + "/" + name);
}

TEST(CertificateFuzzRegression, EveryReproducerEndsInACertificateOrAnInputError) {
  int count = 0;
  for (const auto& entry : std::filesystem::directory_iterator(kRegressions)) {
    const std::string text = grpvss::test::read_text_file(entry.path().string());
    nlohmann::json document;
    try {
      document = nlohmann::json::parse(text);
    } catch (const nlohmann::json::exception&) {
      continue;  // parse_error / out_of_range: the CLI's InputError before certificate_from_json
    }
    try {
      (void)grpvss::certify::certificate_from_json(document, entry.path().string());
    } catch (const grpvss::InputError&) {
    } catch (const std::exception& other) {
      ADD_FAILURE() << entry.path() << ": " << other.what();
    }
    ++count;
  }
  EXPECT_GE(count, 3);
}

TEST(CertificateFuzzRegression, FormatOfAnotherJsonTypeIsAnInputError) {
  // Was json::type_error from document.value("format", "").
  EXPECT_EQ(parse_error_message(reproducer("format-of-another-type.json")),
            "c.json:0: expected a GRPVSS certificate (\"format\": \"grpvss-certificate\")");
}

TEST(CertificateFuzzRegression, VersionOfAnotherJsonTypeIsAnInputError) {
  // Was json::type_error from document.value("version", 0).
  EXPECT_EQ(parse_error_message(reproducer("version-of-another-type.json")),
            "c.json:0: expected certificate version 1");
}

TEST(CertificateFuzzRegression, IntegerFieldBeyondIntRangeIsAnInputError) {
  // Was get<int>() of 1e300: a float-to-int conversion out of range (undefined behaviour).
  EXPECT_EQ(parse_error_message(reproducer("collision-step-beyond-int.json")),
            "c.json:0: expected an integer in int range for field 'collision_step' in the "
            "certificate");
}

TEST(CertificateFuzzRegression, IntegerFieldsAcceptExactlyIntRange) {
  const auto with_step = [](const std::string& value) {
    nlohmann::json document = nlohmann::json::parse(reproducer("collision-step-beyond-int.json"));
    document["collision_step"] = nlohmann::json::parse(value);
    try {
      return std::to_string(
          grpvss::certify::certificate_from_json(document, "c.json").collision_step);
    } catch (const grpvss::InputError&) {
      return std::string("InputError");
    }
  };
  EXPECT_EQ(with_step("2147483647"), "2147483647");
  EXPECT_EQ(with_step("-2147483648"), "-2147483648");
  EXPECT_EQ(with_step("2147483648"), "InputError");
  EXPECT_EQ(with_step("-2147483649"), "InputError");
  EXPECT_EQ(with_step("18446744073709551615"), "InputError");
  EXPECT_EQ(with_step("3.0"), "InputError");
}

}  // namespace

namespace grpvss::certify {
namespace {

TEST(CertificateFuzzRegression, NonPositiveCpSpeedIsAnInputError) {
  // Found by the certificate_checker fuzzer: cp_speed 0 reached Trajectory::plan.
  for (const char* speed : {"0", "-1"}) {
    nlohmann::json document = {{"format", "grpvss-certificate"}, {"version", 1},
                               {"mode", "certified"}, {"tolerance", 0.5},
                               {"offset_shape", "cube"}, {"timing", "independent"},
                               {"cp_speed", nlohmann::json::parse(speed)}};
    EXPECT_THROW(certificate_from_json(document, "c.json"), InputError) << speed;
  }
}

}  // namespace
}  // namespace grpvss::certify

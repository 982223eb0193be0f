// Fuzz target: certificate documents (docs/certificate.md). A JSON syntax error or a number
// beyond double range is reported by nlohmann::json::parse as json::parse_error or
// json::out_of_range (the CLI turns both into InputError); certificate_from_json must answer
// every well-formed JSON document with a Certificate or an InputError, nothing else.
#include <nlohmann/json.hpp>

#include "fuzz_input.hpp"
#include "grpvss/evidence/certificate.hpp"
#include "grpvss/common/input_error.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  nlohmann::json document;
  try {
    document = nlohmann::json::parse(grpvss::fuzz::as_text(data, size));
  } catch (const nlohmann::json::exception&) {
    return 0;  // parse_error, or out_of_range (406) for a number beyond double: the CLI's InputError
  }
  try {
    const grpvss::certify::Certificate certificate =
        grpvss::certify::certificate_from_json(document, "fuzz-certificate.json");
    // What was read must serialise again without throwing.
    (void)grpvss::certify::certificate_to_json(certificate).dump();
  } catch (const grpvss::InputError&) {
  }
  return 0;
}

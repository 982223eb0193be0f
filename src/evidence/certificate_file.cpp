#include "grpvss/evidence/certificate_file.hpp"

#include <fstream>
#include <vector>

#include "grpvss/common/input_error.hpp"

namespace grpvss::certify {
namespace {

using nlohmann::json;

// Parser callback depths: the document is depth 0, its members 1, the elements of a member
// array 2 (nlohmann::json::parser_callback_t).
constexpr int kMemberDepth = 1;
constexpr int kElementDepth = 2;

/// Tracks whether the parser is inside the top-level "segments" array.
class SegmentsTracker {
 public:
  /// Updates the state from one callback; true when this event concerns an element of
  /// "segments" (its start, a primitive element, or its end).
  bool element_event(int depth, json::parse_event_t event, const json& parsed) {
    if (depth == kMemberDepth) {
      if (event == json::parse_event_t::key) in_segments_key_ = parsed == "segments";
      if (event == json::parse_event_t::array_start) in_segments_ = in_segments_key_;
      if (event == json::parse_event_t::array_end) in_segments_ = false;
      return false;
    }
    return in_segments_ && depth == kElementDepth;
  }

 private:
  bool in_segments_key_ = false;
  bool in_segments_ = false;
};

std::ifstream open_certificate(const std::string& path) {
  std::ifstream stream(path, std::ios::binary);
  if (!stream) throw InputError(path, 0, "a readable file");
  return stream;
}

/// json::parse with the CLI's error contract: parse_error, or out_of_range for 1e9999.
void parse(const std::string& path, const json::parser_callback_t& callback, json* document) {
  std::ifstream stream = open_certificate(path);
  try {
    json parsed = json::parse(stream, callback);
    if (document != nullptr) *document = std::move(parsed);
  } catch (const json::exception& error) {
    throw InputError(path, 0, "a JSON document", error.what());
  }
}

}  // namespace

void read_certificate_file(
    const std::string& path, const std::function<void(const CertificateFileHeader&)>& on_header,
    const std::function<void(const SegmentCertificate&)>& on_segment) {
  // Pass 1: everything but the elements of "segments", which are counted and skipped unbuilt
  // (a structure at its start, a primitive as its value).
  CertificateFileHeader header;
  {
    SegmentsTracker tracker;
    std::size_t count = 0;
    const auto skip_segments = [&](int depth, json::parse_event_t event, json& parsed) {
      if (!tracker.element_event(depth, event, parsed)) return true;
      if (event == json::parse_event_t::object_start || event == json::parse_event_t::array_start ||
          event == json::parse_event_t::value) {
        ++count;
        return false;
      }
      return true;
    };
    parse(path, skip_segments, &header.document);
    const bool segments_array = header.document.is_object() &&
                                header.document.contains("segments") &&
                                header.document.at("segments").is_array();
    if (!segments_array) {
      // Nothing was skipped: the whole-document reader says what is wrong (or reads it).
      Certificate whole = certificate_from_json(header.document, path);
      header.segment_count = whole.segments.size();
      std::vector<SegmentCertificate> segments = std::move(whole.segments);
      whole.segments.clear();
      header.certificate = std::move(whole);
      on_header(header);
      for (const SegmentCertificate& segment : segments) on_segment(segment);
      return;
    }
    header.certificate = certificate_header_from_json(header.document, path);
    header.segment_count = count;
  }
  on_header(header);

  // Pass 2: each element of "segments" built alone, converted at its end, then dropped.
  SegmentsTracker tracker;
  const auto each_segment = [&](int depth, json::parse_event_t event, json& parsed) {
    if (!tracker.element_event(depth, event, parsed)) return true;
    if (event == json::parse_event_t::object_end || event == json::parse_event_t::array_end ||
        event == json::parse_event_t::value) {
      on_segment(segment_certificate_from_json(parsed, path));
      return false;
    }
    return true;
  };
  parse(path, each_segment, nullptr);
}

}  // namespace grpvss::certify

#pragma once
/// \file
/// \brief Reading a certificate file in memory independent of its number of steps
/// (`grpvss check-certificate`, docs/reliability.md#resource-bounds).
///
/// The members after "segments" (timing, tolerance, version) are needed before any segment can
/// be checked, so the file is parsed twice with nlohmann's parser callback, never as one
/// document: read_certificate_header() keeps everything but the elements of "segments", which
/// it counts and skips unbuilt; read_certificate_segments() builds one element at a time,
/// converts it and drops it. Errors are those of certificate_from_json() on the whole document.

#include <cstddef>
#include <functional>
#include <string>

#include <nlohmann/json.hpp>

#include "grpvss/evidence/certificate.hpp"

namespace grpvss::certify {

struct CertificateFileHeader {
  Certificate certificate;         ///< without segments
  nlohmann::json document;         ///< the file's JSON with "segments" emptied (e.g. "inputs")
  std::size_t segment_count = 0;   ///< elements of "segments"
};

/// \brief Reads the certificate file at `path`: `on_header` once (the certificate without its
/// segments, the JSON document with "segments" emptied, the number of segments), then
/// `on_segment` with each segment in order.
/// \throws InputError (file = `path`) when the file cannot be read, is not JSON, or is not a
///         well-formed certificate; whatever the callbacks throw.
void read_certificate_file(
    const std::string& path, const std::function<void(const CertificateFileHeader&)>& on_header,
    const std::function<void(const SegmentCertificate&)>& on_segment);

}  // namespace grpvss::certify

#pragma once
/// \file
/// \brief The certificate file (docs/certificate.md): certify::certificate_to_json() plus the
/// `inputs` object, printed with one space of indentation and a final newline; either at once
/// (render_certificate) or while the verification runs (CertificateStream, memory independent
/// of the number of steps, docs/reliability.md#resource-bounds). Both give the same bytes.

#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "grpvss/evidence/certificate.hpp"
#include "grpvss/evidence/verification_observer.hpp"
#include "grpvss/report/spill_file.hpp"
#include "grpvss/report/streamed_json.hpp"

namespace grpvss::report {

/// The certificate file's text: `certificate` (with every segment's steps) and `inputs`
/// (digests and IK name; docs/certificate.md).
std::string render_certificate(const certify::Certificate& certificate,
                               const nlohmann::json& inputs);

/// \brief Writes the certificate file while the verification runs: each segment's steps are
/// rendered as they arrive into a scratch file (SpillFile); finish() writes the head (claim,
/// errors, ... known only at the end) and the segments after it.
class CertificateStream : public certify::VerificationObserver {
 public:
  /// \throws InputError when no scratch file can be created next to `path`.
  CertificateStream(std::string path, bool force);
  ~CertificateStream() override;

  void on_certificate_segment_begin(const certify::SegmentCertificate& segment) override;
  void on_certificate_step(const certify::StepCertificate& step) override;
  void on_certificate_segment_end() override;

  /// Writes and publishes the file: `certificate` is the finished run's (its segments' steps
  /// are not read: they came through the callbacks), `inputs` as for render_certificate().
  /// \throws OutputExistsError, InputError as write_file_atomically(); std::logic_error when a
  ///         segment is still open.
  void finish(const certify::Certificate& certificate, const nlohmann::json& inputs);

 private:
  std::string path_;
  bool force_;
  SpillFile segments_;
  JsonArrayText segments_array_;
  std::optional<JsonArrayText> steps_array_;  ///< the open segment's
  std::string segment_suffix_;                ///< the open segment's text after its steps
};

}  // namespace grpvss::report

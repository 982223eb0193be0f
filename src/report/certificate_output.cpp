#include "grpvss/report/certificate_output.hpp"

#include <stdexcept>
#include <utility>

#include "grpvss/report/atomic_output.hpp"

namespace grpvss::report {
namespace {

constexpr int kIndent = 1;  // the certificate's dump(1)
/// Spaces before the "segments" line: a member of the document. finish() checks it.
constexpr int kSegmentsPad = 1;

nlohmann::json certificate_document(const certify::Certificate& certificate,
                                    const nlohmann::json& inputs) {
  nlohmann::json document = certify::certificate_to_json(certificate);
  document["inputs"] = inputs;
  return document;
}

}  // namespace

std::string render_certificate(const certify::Certificate& certificate,
                               const nlohmann::json& inputs) {
  return certificate_document(certificate, inputs).dump(kIndent) + "\n";
}

CertificateStream::CertificateStream(std::string path, bool force)
    : path_(std::move(path)), force_(force), segments_(path_),
      segments_array_(kIndent, kSegmentsPad) {}

CertificateStream::~CertificateStream() = default;

void CertificateStream::on_certificate_segment_begin(const certify::SegmentCertificate& segment) {
  if (steps_array_) throw std::logic_error("certificate stream: a segment began inside another");
  // The segment as an element of "segments", its steps a placeholder to cut at.
  certify::SegmentCertificate header = segment;
  header.steps.clear();
  nlohmann::json element = certify::certificate_segment_to_json(header);
  element["steps"] = streamed_array_placeholder(0);
  const TemplateCut cut = cut_at_placeholders(
      segments_array_.indent_element(element.dump(kIndent)), 1, kIndent);
  segments_.append(segments_array_.next_element());
  segments_.append(cut.pieces[0]);
  steps_array_.emplace(kIndent, cut.pads[0]);
  segment_suffix_ = cut.pieces[1];
}

void CertificateStream::on_certificate_step(const certify::StepCertificate& step) {
  if (!steps_array_) throw std::logic_error("certificate stream: a step outside a segment");
  segments_.append(steps_array_->next_element());
  segments_.append(steps_array_->indent_element(
      certify::certificate_step_to_json(step).dump(kIndent)));
}

void CertificateStream::on_certificate_segment_end() {
  if (!steps_array_) throw std::logic_error("certificate stream: no segment to end");
  segments_.append(steps_array_->close());
  segments_.append(segment_suffix_);
  steps_array_.reset();
}

void CertificateStream::finish(const certify::Certificate& certificate,
                               const nlohmann::json& inputs) {
  if (steps_array_) throw std::logic_error("certificate stream: a segment was not ended");
  // Everything but the segments (a run that kept its steps must not be copied whole).
  certify::Certificate head;
  head.mode = certificate.mode;
  head.tolerance = certificate.tolerance;
  head.offset_shape = certificate.offset_shape;
  head.timing = certificate.timing;
  head.cp_speed = certificate.cp_speed;
  head.cp_deviation_fraction = certificate.cp_deviation_fraction;
  head.placement_error = certificate.placement_error;
  head.expansion_radius = certificate.expansion_radius;
  head.claim = certificate.claim;
  head.clear_claim = certificate.clear_claim;
  head.collision_step = certificate.collision_step;
  head.allowed_contacts = certificate.allowed_contacts;
  head.names = certificate.names;
  head.self_collision_pairs = certificate.self_collision_pairs;
  head.trajectory_interpolation = certificate.trajectory_interpolation;
  head.start = certificate.start;
  head.errors = certificate.errors;
  nlohmann::json document = certificate_document(head, inputs);
  document["segments"] = streamed_array_placeholder(0);
  const TemplateCut cut = cut_at_placeholders(document.dump(kIndent) + "\n", 1, kIndent);
  if (cut.pads[0] != kSegmentsPad) {
    throw std::logic_error("certificate stream: the segments' indentation is not the one streamed");
  }
  AtomicOutputFile output(path_, force_);
  output.write(cut.pieces[0]);
  segments_.copy_to(output);
  output.write(segments_array_.close());
  output.write(cut.pieces[1]);
  output.commit();
}

}  // namespace grpvss::report

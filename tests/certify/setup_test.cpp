// resolve_setup() is the one place a default that depends on another choice is decided, and
// certificates read their enumerated fields strictly (evidence/setup.hpp, evidence/certificate.hpp).
#include "grpvss/evidence/setup.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "grpvss/common/input_error.hpp"
#include "grpvss/evidence/certificate.hpp"

namespace grpvss::certify {
namespace {

TEST(ResolveSetup, TheOffsetShapeFollowsTheModeUnlessRequested) {
  SetupRequest request;
  request.tolerance = 0.25;
  EXPECT_EQ(resolve_setup(request).cell.offset_shape, geometry::OffsetShape::kRhombicuboctahedron);
  request.mode = ResolutionMode::kThesis;
  EXPECT_EQ(resolve_setup(request).cell.offset_shape, geometry::OffsetShape::kCube);
  request.offset_shape = geometry::OffsetShape::kRhombicuboctahedron;
  EXPECT_EQ(resolve_setup(request).cell.offset_shape, geometry::OffsetShape::kRhombicuboctahedron);
}

TEST(ResolveSetup, EveryOtherChoiceIsCarriedOverUnchanged) {
  SetupRequest request;
  request.tolerance = 0.125;
  request.mode = ResolutionMode::kThesis;
  request.motion.timing = motion::PtpTiming::kSynchronized;
  request.motion.cp_speed = 3.5;
  request.motion.cp_spacing = 0.25;
  request.cp_model.deviation_fraction = 0.5;
  request.cp_model.singular_value_threshold = 2e-3;
  request.limits.max_probes = 77;
  request.limits.min_step_fraction = 1e-8;
  request.limits.certify_floor_fraction = 1e-5;
  request.path_label = "p.txt";
  const VerificationSetup setup = resolve_setup(request);
  EXPECT_EQ(setup.cell.tolerance, 0.125);
  EXPECT_EQ(setup.run.mode, ResolutionMode::kThesis);
  EXPECT_EQ(setup.run.motion.timing, motion::PtpTiming::kSynchronized);
  EXPECT_EQ(setup.run.motion.cp_speed, 3.5);
  EXPECT_EQ(setup.run.motion.cp_spacing, 0.25);
  EXPECT_EQ(setup.run.cp_model.deviation_fraction, 0.5);
  EXPECT_EQ(setup.run.cp_model.singular_value_threshold, 2e-3);
  EXPECT_EQ(setup.run.limits.max_probes, 77);
  EXPECT_EQ(setup.run.limits.min_step_fraction, 1e-8);
  EXPECT_EQ(setup.run.limits.certify_floor_fraction, 1e-5);
  EXPECT_EQ(setup.run.path_label, "p.txt");
}

TEST(EnumText, EveryNameReadsBackAsItsEnumerator) {
  for (auto mode : {ResolutionMode::kCertified, ResolutionMode::kThesis}) {
    EXPECT_EQ(resolution_mode_from_string(to_string(mode)), mode);
  }
  for (auto verdict : {Verdict::kClear, Verdict::kCollision, Verdict::kWithinTolerance,
                       Verdict::kUndecided, Verdict::kError}) {
    EXPECT_EQ(verdict_from_string(to_string(verdict)), verdict);
  }
  for (auto shape : {geometry::OffsetShape::kCube, geometry::OffsetShape::kRhombicuboctahedron}) {
    EXPECT_EQ(geometry::offset_shape_from_string(geometry::to_string(shape)), shape);
  }
  for (auto timing : {motion::PtpTiming::kIndependent, motion::PtpTiming::kSynchronized}) {
    EXPECT_EQ(motion::ptp_timing_from_string(motion::to_string(timing)), timing);
  }
  for (auto kind : {motion::SegmentKind::kPtpJoint, motion::SegmentKind::kPtpWorld,
                    motion::SegmentKind::kCpLine}) {
    EXPECT_EQ(motion::segment_kind_from_string(motion::to_string(kind)), kind);
  }
  EXPECT_FALSE(verdict_from_string("clear"));
  EXPECT_FALSE(motion::ptp_timing_from_string("synchronised"));
}

// A certificate header as certificate_to_json writes it, round-tripped, then with one
// enumerated field misspelt: an input error naming the field and the names it accepts.
TEST(CertificateHeader, EnumeratedFieldsRoundTripAndUnknownNamesAreInputErrors) {
  Certificate certificate;
  certificate.tolerance = 0.5;
  certificate.offset_shape = geometry::OffsetShape::kCube;
  certificate.timing = motion::PtpTiming::kSynchronized;
  certificate.cp_speed = 2.0;
  certificate.claim = Verdict::kWithinTolerance;
  const nlohmann::json document = certificate_to_json(certificate);
  const Certificate read = certificate_header_from_json(document, "c.json");
  EXPECT_EQ(read.mode, ResolutionMode::kCertified);
  EXPECT_EQ(read.offset_shape, geometry::OffsetShape::kCube);
  EXPECT_EQ(read.timing, motion::PtpTiming::kSynchronized);
  EXPECT_EQ(read.claim, Verdict::kWithinTolerance);
  nlohmann::json wrong = document;
  wrong["timing"] = "synchronised";
  try {
    certificate_header_from_json(wrong, "c.json");
    FAIL() << "accepted an unknown timing";
  } catch (const InputError& error) {
    EXPECT_STREQ(error.what(),
                 "c.json:0: expected timing independent or synchronized, found 'synchronised'");
  }
}

}  // namespace
}  // namespace grpvss::certify

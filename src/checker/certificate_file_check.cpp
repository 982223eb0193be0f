#include "grpvss/checker/certificate_file_check.hpp"

#include <optional>

#include "grpvss/common/input_error.hpp"
#include "grpvss/evidence/certificate_file.hpp"

namespace grpvss::certify {

CheckReport check_certificate_file(const std::string& path, const RobotModel& robot,
                                   const Environment& environment, const PathProgram& program,
                                   const motion::KinematicsAccess& kinematics,
                                   const CheckOptions& options,
                                   const std::function<void(const Certificate&)>& on_header) {
  std::optional<CertificateCheck> check;
  std::size_t announced = 0;
  std::size_t delivered = 0;
  const auto changed = [&path] {
    return InputError(path, 0, "a certificate that does not change while it is read");
  };
  read_certificate_file(
      path,
      [&](const CertificateFileHeader& header) {
        if (on_header) on_header(header.certificate);
        announced = header.segment_count;
        check.emplace(robot, environment, program, kinematics, header.certificate, announced,
                      options);
      },
      [&](const SegmentCertificate& segment) {
        if (delivered++ >= announced) throw changed();
        check->add_segment(segment);
      });
  if (!check || delivered != announced) throw changed();
  return check->finish();
}

}  // namespace grpvss::certify

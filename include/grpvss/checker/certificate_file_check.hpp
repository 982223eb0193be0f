#pragma once
/// \file
/// \brief A certificate FILE checked as `grpvss check-certificate` checks it: read one segment
/// at a time (memory independent of its number of steps, docs/reliability.md#resource-bounds)
/// and fed to CertificateCheck. Shared by the CLI and the Python module (python/src/).

#include <functional>
#include <string>

#include "grpvss/checker/certificate_checker.hpp"

namespace grpvss::certify {

/// \brief Reads the certificate file at `path` and checks it against the inputs: the same
/// report as check_certificate() of the whole certificate. `on_header` sees the certificate's
/// header (without segments, with its "inputs") before anything is checked: a caller refuses a
/// certificate made for another motion than it expects by throwing.
/// \throws InputError as read_certificate_file(), or (file = `path`) when the file changes
///         while it is read; whatever `on_header` throws.
CheckReport check_certificate_file(const std::string& path, const RobotModel& robot,
                                   const Environment& environment, const PathProgram& program,
                                   const motion::KinematicsAccess& kinematics,
                                   const CheckOptions& options,
                                   const std::function<void(const Certificate&)>& on_header = {});

}  // namespace grpvss::certify

#pragma once
/// \file
/// \brief The program version written into reports (CMake's project(VERSION)).

namespace grpvss::report {

/// "MAJOR.MINOR.PATCH" of this build.
const char* program_version();

}  // namespace grpvss::report

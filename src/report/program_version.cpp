#include "grpvss/report/program_version.hpp"

#ifndef GRPVSS_VERSION
#error "GRPVSS_VERSION must come from CMake's project(VERSION)"
#endif

namespace grpvss::report {

const char* program_version() { return GRPVSS_VERSION; }

}  // namespace grpvss::report

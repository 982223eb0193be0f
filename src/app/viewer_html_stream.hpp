#pragma once
// The viewer page of `grpvss verify --html` written piece by piece around a streamed report
// (docs/reliability.md#resource-bounds): the bytes of render_viewer_html() for the same report.
#include <functional>
#include <string>

#include "grpvss/report/atomic_output.hpp"

namespace grpvss::app {

/// \throws InputError (file = `html_path`) when this build has no viewer bundle; called before
///         a run, so that a long verification is not wasted.
void require_viewer_bundle(const std::string& html_path);

/// \brief Writes and publishes the page: the template with the title (from `robot_name`), the
/// report appended by `write_report` (compact, `<` escaped: JsonReportStream's script-safe
/// form) and the bundle.
/// \throws OutputExistsError, InputError as write_file_atomically().
void write_viewer_html(const std::string& html_path, bool force, const std::string& robot_name,
                       const std::function<void(report::AtomicOutputFile&)>& write_report);

}  // namespace grpvss::app

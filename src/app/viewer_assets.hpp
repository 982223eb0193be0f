#pragma once
// The report viewer's JavaScript bundle and HTML template, embedded at build time
// (cmake/viewer.cmake generates viewer_assets.cpp from src/viewer).
#include <string>

namespace grpvss::app {

/// The minified three.js viewer (src/viewer/src/*.js bundled by esbuild); empty when the
/// build had no src/viewer/node_modules.
const std::string& viewer_bundle();
/// src/viewer/template.html with the placeholders @GRPVSS_TITLE@, @GRPVSS_REPORT@, @GRPVSS_BUNDLE@.
const std::string& viewer_template();

}  // namespace grpvss::app

#include "urdfdom_parse.hpp"

#include <exception>
#include <mutex>
#include <utility>

#include <console_bridge/console.h>
#include <urdf_parser/urdf_parser.h>

#include "grpvss/common/input_error.hpp"

namespace grpvss::io {
namespace {

// Collects what urdfdom logs through console_bridge while it parses.
class CapturingHandler : public console_bridge::OutputHandler {
 public:
  void log(const std::string& text, console_bridge::LogLevel level, const char* /*filename*/,
           int /*line*/) override {
    if (level >= console_bridge::CONSOLE_BRIDGE_LOG_ERROR) {
      if (first_error.empty()) first_error = text;
    } else if (level == console_bridge::CONSOLE_BRIDGE_LOG_WARN) {
      warnings.push_back(text);
    }
  }
  std::string first_error;
  std::vector<std::string> warnings;
};

// console_bridge's handler is global: one parse at a time, the previous handler restored.
std::mutex& console_mutex() {
  static std::mutex mutex;
  return mutex;
}

void break_link_cycles(urdf::ModelInterface& model) {
  for (auto& [name, link] : model.links_) {
    link->child_links.clear();
    link->child_joints.clear();
    link->parent_joint.reset();
  }
}

}  // namespace

UrdfdomModel parse_with_urdfdom(std::string_view text, const std::string& file) {
  CapturingHandler handler;
  urdf::ModelInterfaceSharedPtr raw;
  std::string exception_text;
  {
    const std::lock_guard<std::mutex> lock(console_mutex());
    const console_bridge::LogLevel level = console_bridge::getLogLevel();
    console_bridge::setLogLevel(console_bridge::CONSOLE_BRIDGE_LOG_WARN);
    console_bridge::useOutputHandler(&handler);
    try {
      raw = urdf::parseURDF(std::string(text));
    } catch (const std::exception& error) {
      exception_text = error.what();
      raw.reset();
    }
    console_bridge::restorePreviousOutputHandler();
    console_bridge::setLogLevel(level);
  }
  if (raw == nullptr) {
    std::string reason = !handler.first_error.empty() ? handler.first_error : exception_text;
    if (reason.empty()) reason = "a file it rejects without a message";
    throw InputError(file, 0, "a URDF urdfdom accepts", reason);
  }
  UrdfdomModel result;
  result.model = std::shared_ptr<const urdf::ModelInterface>(
      raw.get(), [raw](const urdf::ModelInterface*) mutable { break_link_cycles(*raw); });
  for (std::string& warning : handler.warnings) {
    result.warnings.push_back({file, 0, "urdfdom: " + std::move(warning)});
  }
  return result;
}

}  // namespace grpvss::io

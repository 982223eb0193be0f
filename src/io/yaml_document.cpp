#include "yaml_document.hpp"

#include <sstream>

#include <fmt/core.h>
#include <yaml-cpp/eventhandler.h>

#include "grpvss/common/input_error.hpp"

namespace grpvss::io {
namespace {

// Records where the documents start and ignores everything else.
class DocumentStarts : public YAML::EventHandler {
 public:
  void OnDocumentStart(const YAML::Mark& mark) override {
    if (count_ == 1) second_line_ = mark.is_null() ? 0 : mark.line + 1;
    ++count_;
  }
  void OnDocumentEnd() override {}
  void OnNull(const YAML::Mark&, YAML::anchor_t) override {}
  void OnAlias(const YAML::Mark&, YAML::anchor_t) override {}
  void OnScalar(const YAML::Mark&, const std::string&, YAML::anchor_t, const std::string&) override {}
  void OnSequenceStart(const YAML::Mark&, const std::string&, YAML::anchor_t,
                       YAML::EmitterStyle::value) override {}
  void OnSequenceEnd() override {}
  void OnMapStart(const YAML::Mark&, const std::string&, YAML::anchor_t, YAML::EmitterStyle::value) override {}
  void OnMapEnd() override {}

  int second_line() const { return second_line_; }

 private:
  int count_ = 0;
  int second_line_ = 0;
};

}  // namespace

YAML::Node load_single_yaml_document(std::string_view text, const std::string& file_name,
                                     std::string_view what) {
  std::istringstream stream{std::string(text)};
  YAML::Parser parser(stream);
  DocumentStarts starts;
  const bool first = parser.HandleNextDocument(starts);
  if (!first) throw InputError(file_name, 0, fmt::format("one YAML document ({})", what), "none");
  if (parser.HandleNextDocument(starts)) {
    throw InputError(file_name, starts.second_line(), fmt::format("one YAML document ({})", what),
                     "a second document");
  }
  return YAML::Load(std::string(text));
}

}  // namespace grpvss::io

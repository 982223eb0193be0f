#include "grpvss/report/streamed_json.hpp"

#include <algorithm>
#include <stdexcept>

#include <nlohmann/json.hpp>

namespace grpvss::report {

std::string streamed_array_placeholder(int index) {
  return "@grpvss-streamed-array-" + std::to_string(index) + "@";
}

TemplateCut cut_at_placeholders(const std::string& text, int count, int indent) {
  struct Hit {
    std::size_t at;    // start of the quoted placeholder
    std::size_t size;  // length of the quoted placeholder
    int index;
  };
  std::vector<Hit> hits;
  const std::string separator = indent < 0 ? ":" : ": ";
  for (int index = 0; index < count; ++index) {
    // `: "placeholder"`: inside a string every quote is escaped, so this matches only a value.
    const std::string quoted = "\"" + streamed_array_placeholder(index) + "\"";
    const std::string needle = separator + quoted;
    const std::size_t at = text.find(needle);
    if (at == std::string::npos || text.find(needle, at + 1) != std::string::npos) {
      throw std::logic_error("streamed JSON: placeholder " + std::to_string(index) +
                             " missing or repeated in the template");
    }
    hits.push_back({at + separator.size(), quoted.size(), index});
  }
  std::sort(hits.begin(), hits.end(), [](const Hit& a, const Hit& b) { return a.at < b.at; });
  TemplateCut cut;
  std::size_t from = 0;
  for (const Hit& hit : hits) {
    cut.pieces.push_back(text.substr(from, hit.at - from));
    cut.placeholders.push_back(hit.index);
    const std::size_t line_start = text.rfind('\n', hit.at);
    const std::size_t first = line_start == std::string::npos ? 0 : line_start + 1;
    int pad = 0;
    while (first + pad < text.size() && text[first + pad] == ' ') ++pad;
    cut.pads.push_back(indent < 0 ? 0 : pad);
    from = hit.at + hit.size;
  }
  cut.pieces.push_back(text.substr(from));
  return cut;
}

std::string JsonArrayText::next_element() {
  std::string text = any_ ? "," : "[";
  any_ = true;
  if (indent_ >= 0) {
    text += '\n';
    text.append(static_cast<std::size_t>(element_pad()), ' ');
  }
  return text;
}

std::string JsonArrayText::indent_element(const std::string& text) const {
  if (indent_ < 0) return text;
  // Raw newlines occur only between tokens: inside strings they are escaped as \n.
  const std::string line_break = "\n" + std::string(static_cast<std::size_t>(element_pad()), ' ');
  std::string out;
  out.reserve(text.size() + text.size() / 8);
  for (char c : text) {
    if (c == '\n') {
      out += line_break;
    } else {
      out += c;
    }
  }
  return out;
}

std::string JsonArrayText::dump_element(const nlohmann::json& value) const {
  return indent_element(value.dump(indent_, ' ', false, nlohmann::json::error_handler_t::replace));
}

std::string JsonArrayText::close() const {
  if (!any_) return "[]";
  if (indent_ < 0) return "]";
  return "\n" + std::string(static_cast<std::size_t>(pad_), ' ') + "]";
}

}  // namespace grpvss::report

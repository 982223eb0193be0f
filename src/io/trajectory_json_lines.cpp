#include "trajectory_json_lines.hpp"

#include <algorithm>
#include <iterator>

#include "grpvss/common/input_error.hpp"
#include "trajectory_text.hpp"

namespace grpvss::io {
namespace {

using nlohmann::json;

bool is_json_blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; }

/// How far the parser has read, and the line of any offset. The parser reads forward, so the
/// line count advances with a cursor; the few steps back (over one look-ahead character)
/// count backwards.
class ReadPosition {
 public:
  explicit ReadPosition(std::string_view text) : text_(text) {}
  void set_consumed(std::size_t consumed) { consumed_ = consumed; }
  /// Line of the last non-blank character read (the end of the last token).
  int line_of_last_token() {
    std::size_t position = consumed_ == 0 ? 0 : consumed_ - 1;
    while (position > 0 && is_json_blank(text_[position])) --position;
    return line_at(position);
  }
  /// Line of byte `offset` (0-based).
  int line_at(std::size_t offset) {
    offset = std::min(offset, text_.size());
    if (offset >= cursor_) {
      cursor_line_ += static_cast<int>(std::count(text_.begin() + static_cast<std::ptrdiff_t>(cursor_),
                                                  text_.begin() + static_cast<std::ptrdiff_t>(offset), '\n'));
      cursor_ = offset;
      return cursor_line_;
    }
    return cursor_line_ - static_cast<int>(std::count(text_.begin() + static_cast<std::ptrdiff_t>(offset),
                                                      text_.begin() + static_cast<std::ptrdiff_t>(cursor_), '\n'));
  }

 private:
  std::string_view text_;
  std::size_t consumed_ = 0;
  std::size_t cursor_ = 0;
  int cursor_line_ = 1;
};

/// A forward iterator over the text that tells ReadPosition how far nlohmann has read.
class CountingIterator {
 public:
  using iterator_category = std::forward_iterator_tag;
  using value_type = char;
  using difference_type = std::ptrdiff_t;
  using pointer = const char*;
  using reference = const char&;

  CountingIterator(const char* begin, const char* at, ReadPosition* position)
      : begin_(begin), at_(at), position_(position) {}
  reference operator*() const { return *at_; }
  CountingIterator& operator++() {
    ++at_;
    position_->set_consumed(static_cast<std::size_t>(at_ - begin_));
    return *this;
  }
  CountingIterator operator++(int) {
    CountingIterator before = *this;
    ++*this;
    return before;
  }
  bool operator==(const CountingIterator& other) const { return at_ == other.at_; }
  bool operator!=(const CountingIterator& other) const { return at_ != other.at_; }

 private:
  const char* begin_;
  const char* at_;
  ReadPosition* position_;
};

/// The parser callback: records lines by depth (0 root, 1 top-level members, 2 elements of
/// `points`, 3 members of a point) and rejects duplicate keys there.
class LineRecorder {
 public:
  LineRecorder(LocatedJson& located, ReadPosition& position, const std::string& file)
      : located_(located), position_(position), file_(file) {}

  bool on_event(int depth, json::parse_event_t event, const json& parsed) {
    const bool opens = event == json::parse_event_t::object_start ||
                       event == json::parse_event_t::array_start ||
                       event == json::parse_event_t::value;
    if (depth == 0 && opens) located_.root_line = position_.line_of_last_token();
    if (depth == 1 && event == json::parse_event_t::key) on_top_key(parsed.get<std::string>());
    if (depth == 1 && event == json::parse_event_t::array_start) in_points_ = top_key_ == "points";
    if (depth == 1 && (event == json::parse_event_t::array_end ||
                       event == json::parse_event_t::object_end)) {
      in_points_ = false;
    }
    if (in_points_ && depth == 2 && opens) {
      located_.points.emplace_back();
      located_.points.back().start = position_.line_of_last_token();
    }
    if (in_points_ && depth == 3 && event == json::parse_event_t::key &&
        !located_.points.empty()) {
      on_point_key(parsed.get<std::string>());
    }
    return true;
  }

 private:
  void on_top_key(const std::string& key) {
    const int line = position_.line_of_last_token();
    top_key_ = key;
    if (!located_.top_members.emplace(key, line).second) {
      throw InputError(file_, line, "each top-level member once", quoted_text(key) + " again");
    }
  }
  void on_point_key(const std::string& key) {
    JsonPointLines& point = located_.points.back();
    const int line = position_.line_of_last_token();
    const auto known = std::find(kPointMembers.begin(), kPointMembers.end(), key);
    if (known == kPointMembers.end()) {
      if (point.unknown_member_line == 0) {
        point.unknown_member = key;
        point.unknown_member_line = line;
      }
      return;
    }
    int& slot = point.members[static_cast<std::size_t>(known - kPointMembers.begin())];
    if (slot != 0) {
      throw InputError(file_, line,
                       "each member once in points[" + std::to_string(located_.points.size() - 1) + "]",
                       quoted_text(key) + " again");
    }
    slot = line;
  }

  LocatedJson& located_;
  ReadPosition& position_;
  const std::string& file_;
  std::string top_key_;
  bool in_points_ = false;
};

/// nlohmann's message without its `[json.exception.parse_error.101] ` prefix.
std::string without_exception_id(const std::string& message) {
  const std::size_t bracket = message.find("] ");
  return bracket == std::string::npos ? message : message.substr(bracket + 2);
}

}  // namespace

int JsonPointLines::line_of(std::string_view key) const {
  const auto known = std::find(kPointMembers.begin(), kPointMembers.end(), key);
  if (known == kPointMembers.end()) return 0;
  return members[static_cast<std::size_t>(known - kPointMembers.begin())];
}

LocatedJson parse_located_json(std::string_view text, const std::string& file_name) {
  text = without_byte_order_mark(text);
  LocatedJson located;
  ReadPosition position(text);
  LineRecorder recorder(located, position, file_name);
  const char* begin = text.data();
  try {
    located.document = json::parse(
        CountingIterator(begin, begin, &position),
        CountingIterator(begin, begin + text.size(), &position),
        [&recorder](int depth, json::parse_event_t event, json& parsed) {
          return recorder.on_event(depth, event, parsed);
        });
  } catch (const json::parse_error& error) {
    // byte: 1-based offset of the last character read (0 for an empty text).
    const std::size_t offset = error.byte == 0 ? 0 : error.byte - 1;
    throw InputError(file_name, position.line_at(offset), "a JSON document",
                     without_exception_id(error.what()));
  } catch (const json::exception& error) {
    // out_of_range.406: a number beyond double's range, e.g. 1e400.
    throw InputError(file_name, position.line_of_last_token(), "a JSON document",
                     without_exception_id(error.what()));
  }
  return located;
}

}  // namespace grpvss::io

#pragma once
/// \file
/// \brief Writing a JSON document whose large arrays arrive element by element, with exactly
/// the bytes nlohmann::json::dump(indent) prints for the whole document (docs/reliability.md#resource-bounds).
///
/// The document is built as a small template whose large arrays are placeholder strings
/// (streamed_array_placeholder(i)); the template is dumped once and cut at the placeholders
/// (cut_at_placeholders); between the pieces go the arrays, written with JsonArrayText one
/// element at a time. Pretty printing puts an array's elements one indentation step deeper
/// than the line of its key and its closing bracket at that line's indentation, which is what
/// JsonArrayText reproduces (compact printing, indent < 0, has no whitespace at all).

#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

namespace grpvss::report {

/// The placeholder value of streamed array `index` in a template.
std::string streamed_array_placeholder(int index);

/// A dumped template cut at its placeholders.
struct TemplateCut {
  /// pieces[0], array 0, pieces[1], array 1, ..., pieces[n]: placeholders in text order.
  std::vector<std::string> pieces;
  /// Per placeholder (in text order): its index (the `index` of streamed_array_placeholder).
  std::vector<int> placeholders;
  /// Per placeholder (in text order): spaces before the line holding its key.
  std::vector<int> pads;
};

/// \brief Cuts `text`, a template printed with `indent` (as dump(indent) does), at the
/// placeholders 0..count-1, each of which must be an object member's value and occur once.
/// A placeholder string inside another string cannot match: there its quotes are escaped.
/// \throws std::logic_error when a placeholder is missing or repeated.
TemplateCut cut_at_placeholders(const std::string& text, int count, int indent);

/// One JSON array written element by element as dump(indent) prints it inside a document.
class JsonArrayText {
 public:
  /// `pad`: the spaces before the line that holds the array's key (TemplateCut::pads).
  JsonArrayText(int indent, int pad) : indent_(indent), pad_(pad) {}

  /// What goes before the next element: the opening bracket the first time, else a comma;
  /// then (pretty) a newline and the element's indentation.
  std::string next_element();

  /// `value` dumped as an element of this array (invalid UTF-8 replaced, as the report does).
  std::string dump_element(const nlohmann::json& value) const;

  /// `text` (an element dumped with this indent at depth 0) indented as an element here.
  std::string indent_element(const std::string& text) const;

  /// The closing bracket (pretty: after a newline and the key line's indentation), or "[]"
  /// when no element was written.
  std::string close() const;

  /// Spaces before the lines of an element (pad + indent).
  int element_pad() const { return pad_ + (indent_ < 0 ? 0 : indent_); }

 private:
  int indent_;
  int pad_;
  bool any_ = false;
};

}  // namespace grpvss::report

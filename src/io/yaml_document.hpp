#pragma once
/// \file
/// \brief Loading the one YAML document of a text with yaml-cpp, bounded: YAML::LoadAll can
/// loop for ever on some malformed texts (a stray `,` at the start makes every
/// HandleNextDocument call succeed without consuming it), so the documents are counted with
/// at most two parser calls before the first one is loaded.

#include <string>
#include <string_view>

#include <yaml-cpp/yaml.h>

namespace grpvss::io {

/// \brief The first document of `text`.
/// \throws InputError(file_name, line of the second document, "one YAML document ...") when
/// there are more, and YAML::Exception on a syntax error (the caller adds the file).
YAML::Node load_single_yaml_document(std::string_view text, const std::string& file_name,
                                     std::string_view what);

}  // namespace grpvss::io

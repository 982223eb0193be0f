// Blanks between the words of one line of a text file (never the line end itself).
#pragma once

namespace grpvss::io {

inline bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

}  // namespace grpvss::io

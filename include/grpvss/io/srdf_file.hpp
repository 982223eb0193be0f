#pragma once
/// \file
/// \brief Reader of the allowed-collision list of an SRDF file (MoveIt's semantic robot
/// description): its `<disable_collisions link1 link2 reason/>` pairs. Everything else is
/// ignored with a returned warning. docs/urdf.md#srdf.

#include <string>
#include <string_view>
#include <vector>

#include "grpvss/io/input_warning.hpp"

namespace grpvss::io {

/// \brief Two links whose contact is allowed (never checked).
struct DisabledCollision {
  std::string link1;
  std::string link2;
  std::string reason;  ///< `reason` attribute ("Adjacent", "Never", ...), may be empty
  int line = 0;        ///< line of the element
};

/// \brief What an SRDF file says about collisions.
struct SrdfFile {
  std::string robot_name;  ///< `<robot name>`
  /// The pairs disabled by `<disable_collisions>`, in file order, without the pairs a later
  /// `<enable_collisions>` names again (MoveIt lets those override).
  std::vector<DisabledCollision> disabled_collisions;
  /// Ignored elements (groups, end effectors, virtual joints, `<disable_default_collisions>`:
  /// ignoring it only checks more pairs) and duplicate pairs.
  std::vector<InputWarning> warnings;
};

/// \brief Reads an SRDF file.
/// \throws InputError(path, line, ...) for malformed XML, a root that is not `<robot>`, or a
/// `<disable_collisions>`/`<enable_collisions>` without both link names.
SrdfFile read_srdf_file(const std::string& path);

/// \brief As read_srdf_file() on text in memory.
SrdfFile parse_srdf(std::string_view text, const std::string& file_name);

/// \brief Warnings for pairs that name a link not in `link_names` (MoveIt warns too).
std::vector<InputWarning> srdf_links_not_in(const SrdfFile& srdf, const std::string& file_name,
                                            const std::vector<std::string>& link_names);

}  // namespace grpvss::io

#pragma once
/// \file
/// \brief The choices of one verification as words (what `grpvss verify` takes as options and
/// a batch manifest takes as keys), checked and turned into the typed request in one place for
/// both front ends (docs/batch.md, docs/user-guide.md).

#include <string>
#include <vector>

#include "grpvss/evidence/setup.hpp"
#include "grpvss/kinematics/inverse_kinematics.hpp"

namespace grpvss::batch {

/// The words of one verification's inputs and choices; file names as given.
struct VerifyOptions {
  std::string robot_file;
  std::string environment_file;
  std::string path_file;
  double tolerance = 0.0;  ///< Delta > 0, length units
  std::string mode = "certified";
  std::string offset = "auto";
  std::string timing = "independent";
  std::string profile_table;  ///< empty: the ideal trapezoids
  std::string ik = "auto";
  double cp_speed = 1.0;  ///< length units per s
};

/// The accepted words of `mode`, `offset` and `timing`.
const std::vector<std::string>& mode_choices();
const std::vector<std::string>& offset_choices();
const std::vector<std::string>& timing_choices();

/// \brief Checks every choice (not the files): tolerance and cp_speed finite and > 0, the words
/// of mode, offset, timing and ik.
/// \throws InputError(file, line, expected, found) naming the key, e.g.
///         "expected `tolerance`: a finite number > 0, found -1".
void check_verify_options(const VerifyOptions& options, const std::string& file, int line);

/// The words turned into the typed request, once (reads the profile table file).
certify::SetupRequest make_setup_request(const VerifyOptions& options);

/// `ik`: auto, ibm7545, opw, ur, numeric or plugin:PATH.so. \throws InputError ("--ik", line 0).
kinematics::IkChoice parse_ik_choice(const std::string& text);

}  // namespace grpvss::batch

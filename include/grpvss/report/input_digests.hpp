#pragma once
/// \file
/// \brief SHA-256 digests of the three input files, so a report names exactly what it verified.
/// The hashing is Nettle's (grpvss/common/sha256.hpp), never hand-written.

#include <string>

#include "grpvss/common/sha256.hpp"

namespace grpvss::report {

/// One input file as the user named it, and the SHA-256 of its bytes (64 lowercase hex digits).
struct InputFileDigest {
  std::string file;
  std::string sha256;
};

/// The robot, environment and path files of one run, and the unit their lengths are given in.
struct InputDigests {
  InputFileDigest robot;
  InputFileDigest environment;
  InputFileDigest path;
  /// The model's length unit when a cell states it ("m", "mm", "in"): the report's `units.length`.
  /// Empty for thesis files, whose unit is whatever they use ("unit of the input files").
  std::string length_unit;
};

/// SHA-256 of `bytes`, lowercase hex.
using grpvss::sha256_hex;

/// SHA-256 of the file's bytes, lowercase hex.
/// \throws InputError (file = `path`, line 0) if the file cannot be read.
std::string sha256_hex_of_file(const std::string& path);

/// Digests of the three input files, each recorded under the name given here.
/// \throws InputError if a file cannot be read.
InputDigests digest_input_files(const std::string& robot_file,
                                const std::string& environment_file,
                                const std::string& path_file);

}  // namespace grpvss::report

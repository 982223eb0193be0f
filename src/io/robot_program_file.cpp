#include "grpvss/io/robot_program_file.hpp"

#include <filesystem>

#include "grpvss/common/input_error.hpp"
#include "grpvss/io/krl_file.hpp"
#include "grpvss/io/program_lexer.hpp"
#include "grpvss/io/rapid_file.hpp"
#include "grpvss/io/urscript_file.hpp"

namespace grpvss::io {

RobotProgram read_robot_program(const std::string& path) {
  const std::string written = std::filesystem::path(path).extension().string();
  const std::string extension = upper_name(written);
  if (extension == ".SCRIPT") return read_urscript_file(path);
  if (extension == ".SRC") return read_krl_file(path);
  if (extension == ".MOD" || extension == ".MODX" || extension == ".PRG" || extension == ".SYS" ||
      extension == ".SYSX") {
    return read_rapid_file(path);
  }
  if (extension == ".URP") {
    throw InputError(path, 0, "a URScript file (.script): a .urp is a compressed PolyScope program; save it as a script on the robot",
                     "a .urp file");
  }
  if (extension == ".DAT") {
    throw InputError(path, 0, "the .src of a KUKA program (its .dat is read with it)", "a .dat file");
  }
  throw InputError(path, 0,
                   "a robot program: .script (URScript), .src (KUKA KRL), .mod, .modx, .prg, .sys or .sysx (ABB RAPID)",
                   written.empty() ? "no extension" : quote_source(written));
}

std::vector<std::string> robot_program_files(const std::string& path) {
  std::vector<std::string> files{path};
  if (upper_name(std::filesystem::path(path).extension().string()) == ".SRC") {
    for (std::string& data_file : krl_data_files_beside(path)) files.push_back(std::move(data_file));
  }
  return files;
}

}  // namespace grpvss::io

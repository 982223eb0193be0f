#pragma once
// The output files a command was asked to write, checked before any work is done: none names
// the same file as another or as an input, and none exists unless --force
// (docs/user-guide.md#output-files). "-" is standard output (report/atomic_output.hpp).
#include <string>
#include <vector>

namespace grpvss::app {

/// One requested output: the option that named it ("--json") and its path ("" = not asked).
struct RequestedOutput {
  std::string option;
  std::string path;
};

/// \throws InputError(option, 0, ...) naming the second of two outputs that are the same file
/// (or both standard output), an output that is one of `inputs`, or, without `force`, an
/// output file that already exists (OutputExistsError).
void check_requested_outputs(const std::vector<RequestedOutput>& outputs,
                             const std::vector<std::string>& inputs, bool force);

/// True when one of the outputs is standard output: the command then prints its summary on
/// standard error, so that standard output carries the report alone.
bool writes_to_standard_output(const std::vector<RequestedOutput>& outputs);

}  // namespace grpvss::app

#pragma once
/// \file
/// \brief A batch manifest: many verifications, one per job (docs/batch.md). JSON Lines
/// (`.jsonl`, `.json`: one object per line) or YAML (`.yaml`, `.yml`: a top-level `jobs:`
/// sequence), chosen by the extension.

#include <cstddef>
#include <string>
#include <vector>

#include "grpvss/batch/verify_options.hpp"

namespace grpvss::batch {

/// The report files a job asked for ("" = not asked); paths resolved like the inputs.
struct JobOutputs {
  std::string thesis_output;  ///< key `output`: the thesis output file (Appendix A.3)
  std::string json;           ///< the JSON report (docs/report-schema.md)
  std::string html;           ///< the 3-D animation page (docs/viewer.md)
  std::string certificate;    ///< the certificate (docs/certificate.md)
};

/// One job of a manifest. A new input kind (e.g. a cell file) is one more field here and one
/// more key in batch_manifest.cpp's table.
struct BatchJob {
  std::size_t index = 0;  ///< 0-based position in the manifest
  int line = 0;           ///< 1-based line of the job in the manifest
  std::string id;         ///< optional `id` (empty when not given)
  VerifyOptions options;  ///< robot, env, path, tolerance, mode, ... (paths resolved)
  JobOutputs outputs;
};

struct BatchManifest {
  std::string file;  ///< the manifest as named by the caller
  std::vector<BatchJob> jobs;
};

/// The keys a job may have, in the order docs/batch.md lists them.
const std::vector<std::string>& job_keys();

/// \brief Reads and checks a manifest: every job has a model (`cell`, or `robot`, `env` and
/// `tolerance`) and exactly one motion (`path`, `trajectory` or `program`);
/// every key is known and of the right type; every choice is valid (check_verify_options);
/// `certificate` only in certified mode. File names relative to the manifest's folder. The
/// input files themselves are NOT read here (a bad robot file is that job's error).
/// \throws InputError(manifest, line, expected, found) on the first defect.
BatchManifest read_batch_manifest(const std::string& path);

/// \brief As read_batch_manifest() on text in memory; `file_name` decides the format (by its
/// extension), names the manifest in messages and is the base of relative paths.
BatchManifest parse_batch_manifest(const std::string& text, const std::string& file_name);

}  // namespace grpvss::batch

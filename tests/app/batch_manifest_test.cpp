// Batch manifests (docs/batch.md): JSON Lines and YAML read into the same jobs, relative file
// names resolved against the manifest's folder, and every defect refused with the manifest,
// the line and what was expected, before any job runs.
#include <string>

#include <gtest/gtest.h>

#include "grpvss/batch/batch_manifest.hpp"
#include "grpvss/common/input_error.hpp"

namespace {

using grpvss::batch::parse_batch_manifest;

// The message of the InputError that parsing `text` as `file` throws ("" when none).
std::string manifest_parse_error(const std::string& text, const std::string& file = "cells/m.jsonl") {
  try {
    parse_batch_manifest(text, file);
  } catch (const grpvss::InputError& error) {
    return error.what();
  }
  return "";
}

const std::string kJob = R"("robot":"r.txt","env":"e.txt","path":"p.txt","tolerance":0.5)";

TEST(BatchManifest, JsonLinesJobsTakeDefaultsAndResolveFilesAgainstTheManifestFolder) {
  const auto manifest = parse_batch_manifest(
      "{" + kJob + R"(,"id":"first","json":"out/a.json"})" + "\n\n" +
          R"({"robot":"/abs/r.txt","env":"e.txt","path":"../p.txt","tolerance":2,"mode":"thesis",)"
          R"("offset":"cube","timing":"synchronized","cp_speed":3,"ik":"plugin:lib/ik.so","id":7})" "\n",
      "cells/m.jsonl");
  ASSERT_EQ(manifest.jobs.size(), 2u);
  const auto& first = manifest.jobs[0];
  EXPECT_EQ(first.index, 0u);
  EXPECT_EQ(first.line, 1);
  EXPECT_EQ(first.id, "first");
  EXPECT_EQ(first.options.robot_file, "cells/r.txt");
  EXPECT_EQ(first.options.environment_file, "cells/e.txt");
  EXPECT_EQ(first.options.path_file, "cells/p.txt");
  EXPECT_EQ(first.options.tolerance, 0.5);
  EXPECT_EQ(first.options.mode, "certified");
  EXPECT_EQ(first.options.offset, "auto");
  EXPECT_EQ(first.options.timing, "");   // unset: the model decides (independent here)
  EXPECT_EQ(first.options.ik, "auto");
  EXPECT_EQ(first.options.cp_speed, 0.0);  // unset: the cell's, else 1
  EXPECT_EQ(first.outputs.json, "cells/out/a.json");
  EXPECT_EQ(first.outputs.html, "");
  const auto& second = manifest.jobs[1];
  EXPECT_EQ(second.index, 1u);
  EXPECT_EQ(second.line, 3);  // the blank line 2 is skipped, not renumbered
  EXPECT_EQ(second.id, "7");
  EXPECT_EQ(second.options.robot_file, "/abs/r.txt");
  EXPECT_EQ(second.options.path_file, "p.txt");  // cells/../p.txt
  EXPECT_EQ(second.options.mode, "thesis");
  EXPECT_EQ(second.options.offset, "cube");
  EXPECT_EQ(second.options.timing, "synchronized");
  EXPECT_EQ(second.options.cp_speed, 3.0);
  EXPECT_EQ(second.options.ik, "plugin:cells/lib/ik.so");
}

TEST(BatchManifest, YamlJobsAreTheSameJobsWithTheirLines) {
  const auto manifest = parse_batch_manifest(
      "# two jobs\n"
      "jobs:\n"
      "  - id: a\n"
      "    robot: r.txt\n"
      "    env: e.txt\n"
      "    path: p.txt\n"
      "    tolerance: 0.5\n"
      "    output: a.out\n"
      "  - {robot: r.txt, env: e.txt, path: q.txt, tolerance: 1, certificate: q.cert}\n",
      "cells/m.yaml");
  ASSERT_EQ(manifest.jobs.size(), 2u);
  EXPECT_EQ(manifest.jobs[0].line, 3);
  EXPECT_EQ(manifest.jobs[0].id, "a");
  EXPECT_EQ(manifest.jobs[0].options.robot_file, "cells/r.txt");
  EXPECT_EQ(manifest.jobs[0].options.tolerance, 0.5);
  EXPECT_EQ(manifest.jobs[0].outputs.thesis_output, "cells/a.out");
  EXPECT_EQ(manifest.jobs[1].line, 9);
  EXPECT_EQ(manifest.jobs[1].options.path_file, "cells/q.txt");
  EXPECT_EQ(manifest.jobs[1].outputs.certificate, "cells/q.cert");
}

TEST(BatchManifest, UnknownKeysAreRefusedWithTheLineAndTheKnownKeys) {
  EXPECT_EQ(manifest_parse_error("{" + kJob + "}\n{" + kJob + R"(,"cel":"c.yaml"})"),
            "cells/m.jsonl:2: expected one of the job keys id, robot, env, cell, path, trajectory, program, "
            "tolerance, mode, offset, claim, timing, profile_table, ik, cp_speed, start, output, json, "
            "html, certificate, found `cel`");
  EXPECT_EQ(manifest_parse_error("jobs:\n  - robot: r.txt\n    robt: r.txt\n", "m.yml"),
            "m.yml:2: expected one of the job keys id, robot, env, cell, path, trajectory, program, "
            "tolerance, mode, offset, claim, timing, profile_table, ik, cp_speed, start, output, json, "
            "html, certificate, found `robt`");
  EXPECT_EQ(manifest_parse_error("job:\n  - robot: r.txt\n", "m.yml"),
            "m.yml:1: expected the top-level key `jobs`, found `job`");
}

TEST(BatchManifest, ACellJobNeedsOnlyThePathAndNamesNoThesisFiles) {
  const auto manifest = parse_batch_manifest(
      R"({"cell":"ur5e.yaml","path":"p.txt"})" "\n"
      R"({"cell":"ur5e.yaml","path":"q.txt","tolerance":0.002,"timing":"independent"})" "\n",
      "cells/m.jsonl");
  ASSERT_EQ(manifest.jobs.size(), 2u);
  EXPECT_EQ(manifest.jobs[0].options.cell_file, "cells/ur5e.yaml");
  EXPECT_EQ(manifest.jobs[0].options.robot_file, "");
  EXPECT_EQ(manifest.jobs[0].options.tolerance, 0.0);  // unset: the cell's
  EXPECT_EQ(manifest.jobs[0].options.timing, "");      // unset: synchronized for a cell
  EXPECT_EQ(manifest.jobs[1].options.tolerance, 0.002);
  EXPECT_EQ(manifest.jobs[1].options.timing, "independent");
  EXPECT_EQ(manifest_parse_error(R"({"cell":"c.yaml","robot":"r.txt","path":"p"})"),
            "cells/m.jsonl:1: expected either `cell`, or `robot` with `env`, not both");
  EXPECT_EQ(manifest_parse_error(R"({"cell":"c.yaml","tolerance":1})"),
            "cells/m.jsonl:1: expected exactly one of `path`, `trajectory` and `program`, found neither");
  EXPECT_EQ(manifest_parse_error(R"({"cell":"c.yaml","path":"p","cp_speed":0})"),
            "cells/m.jsonl:1: expected `cp_speed`: a finite number > 0, found 0");
  EXPECT_EQ(manifest_parse_error(R"({"env":"e.txt","path":"p","tolerance":1})"),
            "cells/m.jsonl:1: expected a job with the key `robot` (or a `cell`)");
  EXPECT_EQ(manifest_parse_error(R"({"robot":"r.txt","env":"e.txt","path":"p"})"),
            "cells/m.jsonl:1: expected a job with the key `tolerance` (or a `cell`)");
}

TEST(BatchManifest, MissingKeysWrongTypesAndBadChoicesNameTheLine) {
  EXPECT_EQ(manifest_parse_error(R"({"robot":"r.txt","env":"e.txt","tolerance":1})"),
            "cells/m.jsonl:1: expected exactly one of `path`, `trajectory` and `program`, found neither");
  EXPECT_EQ(manifest_parse_error(R"({"robot":"r.txt","env":"e.txt","path":"p","tolerance":"1"})"),
            "cells/m.jsonl:1: expected `tolerance`: a number, found a string");
  EXPECT_EQ(manifest_parse_error(R"({"robot":["r"],"env":"e.txt","path":"p","tolerance":1})"),
            "cells/m.jsonl:1: expected `robot`: a string, found an array");
  EXPECT_EQ(manifest_parse_error(R"({"robot":"r.txt","env":"e.txt","path":3,"tolerance":1})"),
            "cells/m.jsonl:1: expected `path`: a string, found a number");
  EXPECT_EQ(manifest_parse_error("{" + kJob + "}\n{" + kJob + R"(,"tolerance":-1})"),
            "cells/m.jsonl:2: expected `tolerance`: a finite number > 0, found -1");
  EXPECT_EQ(manifest_parse_error("{" + kJob + R"(,"mode":"fast"})"),
            "cells/m.jsonl:1: expected `mode`: certified or thesis, found 'fast'");
  EXPECT_EQ(manifest_parse_error("{" + kJob + R"(,"offset":"ball"})"),
            "cells/m.jsonl:1: expected `offset`: auto, cube or rhombicuboctahedron, found 'ball'");
  EXPECT_EQ(manifest_parse_error("{" + kJob + R"(,"ik":"magic"})"),
            "cells/m.jsonl:1: expected `ik`: auto, ibm7545, opw, ur, numeric or plugin:PATH.so, "
            "found 'magic'");
  EXPECT_EQ(manifest_parse_error("{" + kJob + R"(,"mode":"thesis","certificate":"c"})"),
            "cells/m.jsonl:1: expected `certificate` only with `mode: certified`, found mode "
            "'thesis'");
}

TEST(BatchManifest, MalformedDocumentsAreRefused) {
  EXPECT_EQ(manifest_parse_error("{" + kJob + "}\n[1, 2]\n"),
            "cells/m.jsonl:2: expected a JSON object (one job per line), found an array");
  const std::string broken = manifest_parse_error("{" + kJob + "}\n{\"robot\": \n");
  EXPECT_EQ(broken.rfind("cells/m.jsonl:2: expected a JSON object (one job per line), found "
                         "[json.exception.parse_error.101]",
                         0),
            0u)
      << broken;
  EXPECT_EQ(manifest_parse_error("\n\n"), "cells/m.jsonl:0: expected at least one job, found none");
  EXPECT_EQ(manifest_parse_error("jobs: 3\n", "m.yaml"),
            "m.yaml:1: expected `jobs`: a sequence of jobs, found a scalar");
  EXPECT_EQ(manifest_parse_error("jobs:\n  - 3\n", "m.yaml"),
            "m.yaml:2: expected a job (a mapping), found a scalar");
  EXPECT_EQ(manifest_parse_error("{}", "m.txt"),
            "m.txt:0: expected a manifest named *.jsonl, *.json, *.yaml or *.yml, found '.txt'");
}

}  // namespace

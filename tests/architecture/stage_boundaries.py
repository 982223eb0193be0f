#!/usr/bin/env python3
"""The build enforces the stages' one-way data flow (docs/architecture.md).

For each case, a probe that includes one header is compiled (-fsyntax-only) with the exact
compile command CMake uses for a source of the given stage (from compile_commands.json; a
source compiled in a unity batch takes the batch's command). A
header of a later stage, or another stage's internal header, must fail to compile ("No such
file"); a header of an earlier stage must compile (the control: the probe itself is sound).

Usage: stage_boundaries.py BUILD_DIR/compile_commands.json
"""
import json
import os
import shlex
import subprocess
import sys
import tempfile

# (stage source, header, allowed)
CASES = [
    ("src/io/path_file.cpp", "grpvss/model/robot_model.hpp", True),
    ("src/io/path_file.cpp", "grpvss/kinematics/kinematic_chain.hpp", False),
    ("src/kinematics/forward_kinematics.cpp", "grpvss/motion/trajectory.hpp", False),
    ("src/motion/trajectory.cpp", "grpvss/kinematics/kinematic_chain.hpp", True),
    ("src/motion/trajectory.cpp", "grpvss/io/robot_file.hpp", False),
    ("src/motion/trajectory.cpp", "grpvss/certify/verifier.hpp", False),
    ("src/geometry/gjk.cpp", "grpvss/exact/convex_polytope.hpp", False),
    ("src/exact/certified_query.cpp", "grpvss/geometry/gjk.hpp", True),
    ("src/exact/certified_query.cpp", "grpvss/evidence/certificate.hpp", False),
    ("src/evidence/certificate.cpp", "grpvss/certify/robot_cell.hpp", False),
    # The checker sees the exact predicates, the motion and the certificate format ...
    ("src/checker/certificate_checker.cpp", "grpvss/exact/exact_contact.hpp", True),
    ("src/checker/certificate_checker.cpp", "grpvss/motion/trajectory.hpp", True),
    # ... never the verifier it re-checks.
    ("src/checker/certificate_checker.cpp", "grpvss/certify/robot_cell.hpp", False),
    ("src/checker/certificate_checker.cpp", "grpvss/certify/verifier.hpp", False),
    ("src/checker/certificate_checker.cpp", "certify/cell_probe.hpp", False),
    ("src/certify/verifier.cpp", "grpvss/checker/certificate_checker.hpp", False),
    ("src/certify/verifier.cpp", "grpvss/report/json_report.hpp", False),
    ("src/report/json_report.cpp", "grpvss/certify/robot_cell.hpp", True),
    ("src/report/json_report.cpp", "certify/cell_probe.hpp", False),
    # The batch runs the verifier and the report writers; nothing before it sees the batch.
    ("src/batch/batch_runner.cpp", "grpvss/report/json_report_stream.hpp", True),
    ("src/batch/batch_runner.cpp", "grpvss/certify/verifier.hpp", True),
    ("src/batch/batch_runner.cpp", "grpvss/checker/certificate_checker.hpp", False),
    ("src/report/json_report.cpp", "grpvss/batch/batch_runner.hpp", False),
]


def probe_command(entry, probe):
    args = shlex.split(entry["command"]) if "command" in entry else list(entry["arguments"])
    out, skip = [], False
    for arg in args:
        if skip:
            skip = False
            continue
        if arg == "-o":
            skip = True
            continue
        if arg in ("-c", entry["file"]) or arg.endswith(os.path.basename(entry["file"])):
            continue
        out.append(arg)
    return out + ["-fsyntax-only", probe]


def unity_members(entry):
    """The sources a unity batch file (CMake UNITY_BUILD) #includes, as absolute paths."""
    members = []
    with open(entry["file"]) as handle:
        for line in handle:
            if line.startswith('#include "'):
                members.append(line.split('"')[1])
    return members


def entries_by_source(database, root):
    """Each source's compile entry; a source compiled inside a unity batch takes the batch's."""
    by_file = {}
    for entry in database:
        if "/Unity/unity_" in entry["file"]:
            for member in unity_members(entry):
                by_file[os.path.relpath(member, root)] = entry
        else:
            by_file[os.path.relpath(entry["file"], root)] = entry
    return by_file


def main():
    database = json.load(open(sys.argv[1]))
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    root = os.path.dirname(root)
    by_file = entries_by_source(database, root)
    failures = 0
    with tempfile.TemporaryDirectory() as directory:
        for index, (source, header, allowed) in enumerate(CASES):
            entry = by_file.get(source)
            if entry is None:
                print(f"FAIL {source}: not in the compile database")
                failures += 1
                continue
            probe = os.path.join(directory, f"probe_{index}.cpp")
            with open(probe, "w") as handle:
                handle.write(f'#include "{header}"\n')
            result = subprocess.run(probe_command(entry, probe), cwd=entry["directory"],
                                    capture_output=True, text=True)
            compiled = result.returncode == 0
            # g++ says "No such file or directory", clang "file not found".
            missing = "No such file" in result.stderr or "file not found" in result.stderr
            ok = compiled if allowed else (not compiled and missing)
            verdict = "ok  " if ok else "FAIL"
            print(f"{verdict} {source} {'may' if allowed else 'must not'} include {header}")
            if not ok:
                print(result.stderr[:2000])
                failures += 1
    print(f"{len(CASES) - failures} of {len(CASES)} stage boundaries hold")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())

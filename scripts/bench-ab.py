#!/usr/bin/env python3
"""A/B of the benchmark binary at two commits in the same run (issue #22 point 6,
docs/performance.md#ab-against-a-starting-commit).

Usage: scripts/bench-ab.py BASE [--build DIR] [--filter REGEX] [--rounds N] [--min-time S]
                           [--a-binary FILE]

A = grpvss_bench built from commit BASE (exported with `git archive` into
$TMPDIR/grpvss-ab-<sha>, configured Release with ccache, only the grpvss_bench target);
B = the current build's grpvss_bench (--build, default ./build). The two binaries run in
--rounds interleaved rounds (A B, B A, A B, ...) with the same filter; the table gives the
median (and range) of the CPU time per benchmark and B / A. The default filter is the thesis
Table 3 operations (thesis-format inputs). --a-binary FILE uses an A binary built earlier
(BASE then only labels it).
"""
import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DEFAULT_FILTER = "BM_VerifyPtpOperation|BM_VerifyCpOperation|BM_RobotCellSetup/0"


def build_base(commit, jobs):
    sha = subprocess.run(["git", "-C", HERE, "rev-parse", commit], check=True,
                         capture_output=True, text=True).stdout.strip()
    source = os.path.join(tempfile.gettempdir(), f"grpvss-ab-{sha[:12]}")
    binary = os.path.join(source, "build", "tests", "grpvss_bench")
    if not os.path.exists(os.path.join(source, "CMakeLists.txt")):
        os.makedirs(source, exist_ok=True)
        archive = subprocess.Popen(["git", "-C", HERE, "archive", sha], stdout=subprocess.PIPE)
        subprocess.run(["tar", "-x", "-C", source], stdin=archive.stdout, check=True)
        archive.wait()
        modules = os.path.join(HERE, "src", "viewer", "node_modules")
        if os.path.exists(modules):  # the configure step requires the viewer bundle's modules
            os.symlink(os.path.realpath(modules), os.path.join(source, "src", "viewer", "node_modules"))
    # A's robot benchmarks read ../shared/robots beside A's source, as B's do beside ours.
    shared = os.path.join(os.path.dirname(source), "shared")
    ours = os.path.join(os.path.dirname(HERE), "shared")
    if not os.path.exists(shared) and os.path.isdir(ours):
        os.symlink(os.path.realpath(ours), shared)
    configure = ["cmake", "-S", source, "-B", os.path.join(source, "build"), "-DCMAKE_BUILD_TYPE=Release"]
    if subprocess.run(["sh", "-c", "command -v ccache"], capture_output=True).returncode == 0:
        configure.append("-DCMAKE_CXX_COMPILER_LAUNCHER=ccache")
    subprocess.run(configure, check=True, stdout=subprocess.DEVNULL)
    subprocess.run(["cmake", "--build", os.path.join(source, "build"), "-j", str(jobs),
                    "--target", "grpvss_bench"], check=True, stdout=subprocess.DEVNULL)
    return binary, sha


def run_once(binary, bench_filter, min_time):
    with tempfile.NamedTemporaryFile(suffix=".json") as out:
        subprocess.run([binary, f"--benchmark_filter={bench_filter}", f"--benchmark_min_time={min_time}",
                        f"--benchmark_out={out.name}", "--benchmark_out_format=json"],
                       check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        results = json.load(open(out.name))
    scale = {"ns": 1e-3, "us": 1.0, "ms": 1e3, "s": 1e6}
    return {e["name"]: e["cpu_time"] * scale[e["time_unit"]] for e in results["benchmarks"]}


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("base")
    parser.add_argument("--build", default=os.path.join(HERE, "build"))
    parser.add_argument("--filter", default=DEFAULT_FILTER)
    parser.add_argument("--rounds", type=int, default=8)
    parser.add_argument("--min-time", default="0.5")
    parser.add_argument("--jobs", type=int, default=int(os.environ.get("GRPVSS_JOBS", "2")))
    parser.add_argument("--a-binary")
    args = parser.parse_args()
    if args.a_binary:
        a_binary, sha = args.a_binary, args.base
    else:
        a_binary, sha = build_base(args.base, args.jobs)
    b_binary = os.path.join(args.build, "tests", "grpvss_bench")
    print(f"# A = {sha[:12]}, B = {b_binary}; load average %.1f %.1f %.1f" % os.getloadavg())
    samples = {"A": {}, "B": {}}
    for round_number in range(args.rounds):
        order = [("A", a_binary), ("B", b_binary)]
        for label, binary in order if round_number % 2 == 0 else reversed(order):
            for name, value in run_once(binary, args.filter, args.min_time).items():
                samples[label].setdefault(name, []).append(value)
    print(f"\n| benchmark | A: {sha[:12]} | B: now | B / A |\n|---|---|---|---|")
    for name in samples["B"]:
        a, b = samples["A"].get(name), samples["B"][name]
        cell = lambda s: f"{statistics.median(s):.1f} us ({min(s):.1f}-{max(s):.1f})"
        ratio = f"{statistics.median(b) / statistics.median(a):.2f}" if a else "–"
        print(f"| `{name}` | {cell(a) if a else '–'} | {cell(b)} | {ratio} |")
    print("\n# load average %.1f %.1f %.1f at the end" % os.getloadavg())


if __name__ == "__main__":
    main()

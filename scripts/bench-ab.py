#!/usr/bin/env python3
"""A/B of the benchmark binary at two commits in the same run (issue #22 point 6,
docs/performance.md#ab-against-a-starting-commit).

Usage: scripts/bench-ab.py BASE [--build DIR] [--filter REGEX] [--rounds N] [--min-time S]
                           [--a-binary FILE] [--b-binary FILE] [--paired] [--cpu N]

A = grpvss_bench built from commit BASE (exported with `git archive` into
$TMPDIR/grpvss-ab-<sha>, configured Release with ccache, only the grpvss_bench target);
B = the current build's grpvss_bench (--build, default ./build). The two binaries run in
--rounds interleaved rounds (A B, B A, A B, ...) with the same filter; the table gives the
median (and range) of the CPU time per benchmark and B / A. The default filter is the thesis
Table 3 operations (thesis-format inputs). --a-binary FILE uses an A binary built earlier
(BASE then only labels it); --b-binary FILE replaces B (the same file as A gives the noise floor).

--paired runs each benchmark on its own, A and B back to back (A B, then B A, ...), and adds
the median and range of the per-pair ratios B / A. On a VM whose vCPU speed drifts over
minutes, whole-binary rounds compare runs that lie minutes apart; a pair lies seconds apart.
--cpu N pins both binaries to CPU N (sched_setaffinity), so they share one vCPU's speed.
"""
import argparse
import json
import os
import re
import statistics
import subprocess
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


def pinned_to(cpu):
    """A preexec_fn pinning the child to `cpu`, or None when cpu is None."""
    if cpu is None:
        return None
    return lambda: os.sched_setaffinity(0, {cpu})


def run_once(binary, bench_filter, min_time, cpu=None):
    with tempfile.NamedTemporaryFile(suffix=".json") as out:
        subprocess.run([binary, f"--benchmark_filter={bench_filter}", f"--benchmark_min_time={min_time}",
                        f"--benchmark_out={out.name}", "--benchmark_out_format=json"],
                       check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                       preexec_fn=pinned_to(cpu))
        results = json.load(open(out.name))
    scale = {"ns": 1e-3, "us": 1.0, "ms": 1e3, "s": 1e6}
    return {e["name"]: e["cpu_time"] * scale[e["time_unit"]] for e in results["benchmarks"]}


def listed_benchmarks(binary, bench_filter):
    """The names the filter selects, in the binary's order."""
    listed = subprocess.run([binary, f"--benchmark_filter={bench_filter}", "--benchmark_list_tests"],
                            check=True, capture_output=True, text=True).stdout
    return listed.split()


def round_order(binaries, round_number):
    """A B in even rounds, B A in odd ones: neither binary always runs first."""
    order = [("A", binaries["A"]), ("B", binaries["B"])]
    return order if round_number % 2 == 0 else order[::-1]


def interleaved_samples(binaries, bench_filter, rounds, min_time, cpu=None):
    """Whole-binary rounds: every selected benchmark in one run of A, then of B (or B, A)."""
    samples = {"A": {}, "B": {}}
    for round_number in range(rounds):
        for label, binary in round_order(binaries, round_number):
            for name, value in run_once(binary, bench_filter, min_time, cpu).items():
                samples[label].setdefault(name, []).append(value)
    return samples


def paired_samples(binaries, names, rounds, min_time, cpu=None):
    """Per benchmark, `rounds` pairs of back-to-back runs; returns the samples and, per
    benchmark, the pair ratios B / A."""
    samples = {"A": {}, "B": {}}
    ratios = {}
    for name in names:
        exact = "^" + re.escape(name) + "$"
        for round_number in range(rounds):
            pair = {}
            for label, binary in round_order(binaries, round_number):
                pair[label] = run_once(binary, exact, min_time, cpu)[name]
                samples[label].setdefault(name, []).append(pair[label])
            ratios.setdefault(name, []).append(pair["B"] / pair["A"])
    return samples, ratios


def table(samples, ratios, a_label):
    """The Markdown table: medians and ranges, B / A of the medians, and with pairs the
    median (range) of the pair ratios."""
    paired = ratios is not None
    lines = [f"| benchmark | A: {a_label} | B: now | B / A |" + (" pairs B / A |" if paired else ""),
             "|---|---|---|---|" + ("---|" if paired else "")]
    for name in samples["B"]:
        a, b = samples["A"].get(name), samples["B"][name]
        cell = lambda s: f"{statistics.median(s):.1f} us ({min(s):.1f}-{max(s):.1f})"
        ratio = f"{statistics.median(b) / statistics.median(a):.3f}" if a else "–"
        row = f"| `{name}` | {cell(a) if a else '–'} | {cell(b)} | {ratio} |"
        if paired:
            r = ratios.get(name)
            row += f" {statistics.median(r):.3f} ({min(r):.3f}-{max(r):.3f}) |" if r else " – |"
        lines.append(row)
    return "\n".join(lines)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("base")
    parser.add_argument("--build", default=os.path.join(HERE, "build"))
    parser.add_argument("--filter", default=DEFAULT_FILTER)
    parser.add_argument("--rounds", type=int, default=8)
    parser.add_argument("--min-time", default="0.5")
    parser.add_argument("--jobs", type=int, default=int(os.environ.get("GRPVSS_JOBS", "2")))
    parser.add_argument("--a-binary")
    parser.add_argument("--b-binary")
    parser.add_argument("--paired", action="store_true")
    parser.add_argument("--cpu", type=int)
    args = parser.parse_args()
    if args.a_binary:
        a_binary, sha = args.a_binary, args.base
    else:
        a_binary, sha = build_base(args.base, args.jobs)
    b_binary = args.b_binary or os.path.join(args.build, "tests", "grpvss_bench")
    binaries = {"A": a_binary, "B": b_binary}
    pinning = f", pinned to CPU {args.cpu}" if args.cpu is not None else ""
    print(f"# A = {sha[:12]}, B = {b_binary}{pinning}; load average %.1f %.1f %.1f" % os.getloadavg())
    if args.paired:
        names = listed_benchmarks(b_binary, args.filter)
        samples, ratios = paired_samples(binaries, names, args.rounds, args.min_time, args.cpu)
    else:
        samples, ratios = interleaved_samples(binaries, args.filter, args.rounds, args.min_time, args.cpu), None
    print()
    print(table(samples, ratios, sha[:12]))
    print("\n# load average %.1f %.1f %.1f at the end" % os.getloadavg())


if __name__ == "__main__":
    main()

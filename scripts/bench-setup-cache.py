#!/usr/bin/env python3
"""Whole-process `grpvss verify` on the thesis sample (data/ibm7545) with the set-up cache off,
empty (a new directory every run: build and write the entry) and warm (docs/cache.md,
docs/performance.md#set-up-cache). Runs the cases interleaved (so that load from other
processes spreads over all of them) and prints the median and mean elapsed time and CPU time
(user + system, from wait4's rusage, microsecond resolution) per case.

Usage: scripts/bench-setup-cache.py [GRPVSS_BINARY] [RUNS]
"""
import os
import statistics
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def run(command):
    """Elapsed and CPU seconds of one process."""
    start = time.perf_counter()
    process = subprocess.Popen(command, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    _, _, usage = os.wait4(process.pid, 0)
    return time.perf_counter() - start, usage.ru_utime + usage.ru_stime


def main():
    grpvss = sys.argv[1] if len(sys.argv) > 1 else os.path.join(HERE, "build", "grpvss")
    runs = int(sys.argv[2]) if len(sys.argv) > 2 else 30
    data = os.path.join(HERE, "data", "ibm7545")
    verify = [grpvss, "verify", "--robot", f"{data}/robot.txt", "--env", f"{data}/environment.txt",
              "--path", f"{data}/path.txt", "--tolerance", "0.5", "--quiet"]
    with tempfile.TemporaryDirectory() as work:
        warm = os.path.join(work, "warm")
        run(verify + ["--cache-dir", warm])
        cases = {"no-cache": lambda i: ["--no-cache"],
                 "empty": lambda i: ["--cache-dir", os.path.join(work, f"empty-{i}")],
                 "warm": lambda i: ["--cache-dir", warm]}
        times = {name: [] for name in cases}
        for i in range(runs):
            for name, options in cases.items():
                times[name].append(run(verify + options(i)))
    for name, samples in times.items():
        elapsed = [s[0] * 1000 for s in samples]
        cpu = [s[1] * 1000 for s in samples]
        print(f"{name:>9}: elapsed median {statistics.median(elapsed):6.1f} ms "
              f"(mean {statistics.mean(elapsed):6.1f}); CPU median {statistics.median(cpu):6.1f} ms "
              f"(mean {statistics.mean(cpu):6.1f}), {len(samples)} runs")


if __name__ == "__main__":
    main()

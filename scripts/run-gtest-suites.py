#!/usr/bin/env python3
"""Runs the test binary's gtest cases that ctest would run, one process per suite.

Under the sanitizers a test process costs ~0.45 s to start and exit (ASan registers the
globals, LeakSanitizer scans UBSan's ~100 MB of check data at exit): with ~1,000 cases that is
about 7 CPU minutes of starts. Grouped by suite (~200 of them) the cases are the same, chosen by
ctest's own selection (its labels, `-LE heavy`), with the environment ctest gives them
(tests/CMakeLists.txt: XDG_CACHE_HOME). A failing suite prints its output; the exit status is
1 when any suite failed or timed out (docs/reliability.md#ci-time).

Usage: run-gtest-suites.py BUILD_DIR [--jobs N] [--timeout S] [ctest selection options...]
"""
import argparse
import collections
import concurrent.futures
import os
import re
import subprocess
import sys
import time


def selected_cases(build_dir, selection):
    """The gtest cases (Suite.Name) ctest selects with `selection`, in ctest's order."""
    listing = subprocess.run(["ctest", "-N", *selection], cwd=build_dir, check=True,
                             capture_output=True, text=True).stdout
    names = re.findall(r"^\s*Test\s+#\d+: (\S+)$", listing, re.M)
    return [name for name in names if "." in name]  # the other tests have no suite


def run_suite(binary, suite, cases, environment, timeout):
    started = time.monotonic()
    try:
        run = subprocess.run([binary, "--gtest_filter=" + ":".join(cases)], env=environment,
                             capture_output=True, text=True, timeout=timeout)
        status, output = run.returncode, run.stdout + run.stderr
    except subprocess.TimeoutExpired as expired:
        status = "timeout"
        output = (expired.stdout or b"").decode(errors="replace") + (expired.stderr or b"").decode(errors="replace")
    if status == 0:
        # Every case ran and passed: none skipped (a skip is no pass), none missing.
        passed = re.search(r"^\[  PASSED  \] (\d+) tests?\.$", output, re.M)
        if "[  SKIPPED ]" in output:
            status = "a case was skipped"
        elif not passed or int(passed.group(1)) != len(cases):
            status = f"{passed.group(1) if passed else 'no'} cases passed of {len(cases)}"
    return suite, len(cases), status, output, time.monotonic() - started


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("build_dir")
    parser.add_argument("--jobs", type=int, default=os.cpu_count() or 1)
    parser.add_argument("--timeout", type=float, default=1800.0, help="seconds per suite")
    args, selection = parser.parse_known_args()
    binary = os.path.join(args.build_dir, "tests", "grpvss_tests")
    cases = selected_cases(args.build_dir, selection)
    if not cases:
        print("run-gtest-suites: ctest selects no gtest case", file=sys.stderr)
        return 1
    suites = collections.OrderedDict()
    for case in cases:
        suites.setdefault(case.split(".", 1)[0], []).append(case)
    environment = dict(os.environ, XDG_CACHE_HOME=os.path.join(args.build_dir, "test-cache"))
    failed = []
    started = time.monotonic()
    with concurrent.futures.ThreadPoolExecutor(max_workers=args.jobs) as pool:
        futures = [pool.submit(run_suite, binary, suite, members, environment, args.timeout)
                   for suite, members in suites.items()]
        for done, future in enumerate(concurrent.futures.as_completed(futures), 1):
            suite, count, status, output, seconds = future.result()
            verdict = "Passed" if status == 0 else f"Failed ({status})"
            print(f"{done:3d}/{len(suites)} {suite} ({count} cases) {verdict} {seconds:.1f} s", flush=True)
            if status != 0:
                failed.append(suite)
                print(output, flush=True)
    print(f"run-gtest-suites: {len(cases)} cases in {len(suites)} suites, "
          f"{len(failed)} suite(s) failed, {time.monotonic() - started:.0f} s")
    for suite in failed:
        print(f"  FAILED: {suite}")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())

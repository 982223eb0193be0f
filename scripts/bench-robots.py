#!/usr/bin/env python3
"""Reruns the real-robot benchmarks against FCL and prints the tables of
docs/performance.md#real-robots-and-fcl (issue #22): per configuration, per trajectory, the
misses, whole processes cold and warm, and the targets met or missed.

Usage: scripts/bench-robots.py [--build DIR] [--repetitions N] [--runs N] [--json FILE]
                               [--filter REGEX] [--no-processes] [--cpu N]

--json FILE   read the benchmark results from FILE (an earlier --benchmark_out) instead of
              running grpvss_bench (the file is written there when it does not exist; a FILE
              older than grpvss_bench is refused).
--filter      benchmark filter (default: every robot benchmark and Table 3's CP operation).
--cpu N       pin this script and everything it runs to CPU N (a VM's vCPUs may differ in
              speed, and a process that migrates changes speed mid-run).
Benchmarks: CPU-time medians of --repetitions repetitions, randomly interleaved across the
benchmarks (Google Benchmark's --benchmark_enable_random_interleaving), so that a change of
the machine's speed during the run reaches GRPVSS's rows and the FCL peers' alike rather than
whichever ran then (the machine's load is printed: other processes inflate wall time; CPU time
is what the tables use).
Whole processes: --runs interleaved runs each of `grpvss verify` cold (--no-cache), warm
(set-up cache hit) and of `grpvss_fcl_peer check` (FCL sampled at Delta/4) on the same files;
CPU = user + system.
"""
import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
ROBOTS = ["UR5e", "Panda", "six-axis"]
DEFAULT_FILTER = "BM_RobotConfiguration|BM_RobotTrajectory|BM_RobotMisses|BM_VerifyCpOperation/0|BM_VerifyCpOperationThroughAPost/0"


def load_text():
    return "load average %.1f %.1f %.1f" % os.getloadavg()


def run_benchmarks(build, repetitions, json_file, bench_filter):
    binary = os.path.join(build, "tests", "grpvss_bench")
    if json_file and os.path.exists(json_file):
        # Results older than the binary are another build's: a stale file once gave a table
        # from before the revolution route without a word.
        if os.path.exists(binary) and os.path.getmtime(json_file) < os.path.getmtime(binary):
            sys.exit(f"bench-robots.py: {json_file} is older than {binary}: its results are another "
                     "build's; remove it or name a new file")
        with open(json_file) as f:
            return json.load(f)
    out = json_file or tempfile.mktemp(suffix=".json")
    command = [binary, f"--benchmark_filter={bench_filter}",
               f"--benchmark_repetitions={repetitions}", "--benchmark_report_aggregates_only=true",
               "--benchmark_enable_random_interleaving=true",
               f"--benchmark_out={out}", "--benchmark_out_format=json"]
    print(f"# running {' '.join(command)} ({load_text()})", file=sys.stderr)
    subprocess.run(command, check=True, stdout=subprocess.DEVNULL)
    with open(out) as f:
        return json.load(f)


def medians(results):
    """run_name -> the median entry (CPU time in microseconds, counters)."""
    table = {}
    for entry in results["benchmarks"]:
        if entry.get("aggregate_name", "median") != "median":
            continue
        scale = {"ns": 1e-3, "us": 1.0, "ms": 1e3, "s": 1e6}[entry["time_unit"]]
        entry = dict(entry)
        entry["cpu_us"] = entry["cpu_time"] * scale
        table[entry["run_name"]] = entry
    return table


def us(value):
    if value is None:
        return "–"
    if value >= 10000:
        return f"{value / 1000:.1f} ms"
    return f"{value:.0f} us" if value >= 100 else f"{value:.3g} us"


def ratio(peer, ours):
    if peer is None or ours is None:
        return "–"
    return f"{peer / ours:.2f}x" if peer < ours else f"{peer / ours:.1f}x"


def cpu(table, name):
    entry = table.get(name)
    return entry["cpu_us"] if entry else None


def configuration_table(table):
    print("| robot | obstacles | GRPVSS certified verdict (ConfigurationCheck) | FCL collide "
          "(DynamicAABBTree) | FCL / GRPVSS verdict | GRPVSS certified clearances (CellProbe) "
          "| FCL / GRPVSS clearances |")
    print("|---|---|---|---|---|---|---|")
    for robot in range(3):
        for obstacles in (10, 100, 1000):
            per_config = {name: cpu(table, f"BM_RobotConfiguration{name}/{robot}/{obstacles}")
                          for name in ("CheckGrpvss", "Fcl", "Grpvss")}
            verdict, peer, probe = (value / 64 if value else None for value in per_config.values())
            print(f"| {ROBOTS[robot]} | {obstacles} | {us(verdict)} | {us(peer)} | {ratio(peer, verdict)} "
                  f"| {us(probe)} | {ratio(peer, probe)} |")


def trajectory_table(table):
    print("| robot | obstacles | waypoints | Delta | GRPVSS certified (steps) | FCL Delta/4 (samples) "
          "| ratio | FCL 1 deg (samples) | ratio | FCL CA (calls) | ratio |")
    print("|---|---|---|---|---|---|---|---|---|---|---|")
    for robot in range(3):
        for obstacles in (10, 100, 1000):
            for waypoints in (10, 100):
                for delta in (1, 5):
                    key = f"{robot}/{obstacles}/{waypoints}"
                    ours = table.get(f"BM_RobotTrajectoryGrpvss/{key}/{delta}")
                    sampled = table.get(f"BM_RobotTrajectoryFclSampled/{key}/{delta}")
                    degree = table.get(f"BM_RobotTrajectoryFclOneDegree/{key}/5")
                    ca = table.get(f"BM_RobotTrajectoryFclConservativeAdvancement/{key}/5")
                    if not ours:
                        continue
                    cells = [f"{us(ours['cpu_us'])} ({ours.get('steps', 0):.0f})"]
                    for peer, counter in ((sampled, "queries"), (degree, "queries"), (ca, "queries")):
                        if peer:
                            # *: the peer reported a contact on this certified-clear path and stopped there
                            mark = "*" if peer.get("collision") else ""
                            cells += [f"{us(peer['cpu_us'])} ({peer.get(counter, 0):.0f}){mark}",
                                      ratio(peer["cpu_us"], ours["cpu_us"])]
                        else:
                            cells += ["–", "–"]
                    print(f"| {ROBOTS[robot]} | {obstacles} | {waypoints} | {delta} mm | " + " | ".join(cells) + " |")


def misses_table(table):
    print("| cell | Delta | COLLISION paths (an obstacle hit) | self-collision only (not scored) "
          "| CLEAR | other verdicts | missed: FCL Delta/4 | FCL 1 deg "
          "| FCL CA | false alarms (Delta/4, 1 deg, CA) |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    cells = ((4, "benchmark cell (2 of 11 near obstacles thin)"), (1, "every near obstacle thin"))
    for (thin, cell), delta in ((c, d) for c in cells for d in (1, 5)):
        e = table.get(f"BM_RobotMissesUr5e/{delta}/{thin}/iterations:1")
        if not e:
            continue
        g = lambda k: f"{e.get(k, 0):.0f}"
        print(f"| {cell} | {delta} mm | {g('collision')} | {g('self_collision')} | {g('clear')} | {g('other')} "
              f"| {g('missed_sampled')} | {g('missed_one_degree')} | {g('missed_ca')} "
              f"| {g('false_sampled')}, {g('false_one_degree')}, {g('false_ca')} |")


def run_process(command):
    start = time.perf_counter()
    process = subprocess.Popen(command, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    _, status, usage = os.wait4(process.pid, 0)
    return time.perf_counter() - start, usage.ru_utime + usage.ru_stime, os.waitstatus_to_exitcode(status)


def process_cases(build, work):
    grpvss = os.path.join(build, "grpvss")
    peer = os.path.join(build, "tests", "grpvss_fcl_peer")
    cases = []
    for robot, obstacles in (("ur5e", 100), ("panda", 100), ("sixaxis", 100), ("ur5e", 1000)):
        subprocess.run([peer, "generate", work, robot, str(obstacles)], check=True)
        for waypoints in (10, 100):
            stem = f"{work}/{robot}-{obstacles}"
            inputs = ["--cell", f"{stem}.yaml", "--path", f"{stem}-{waypoints}.txt"]
            cases.append((f"{robot}, {obstacles} obstacles, {waypoints} waypoints, Delta 5 mm",
                          [grpvss, "verify", *inputs, "--quiet"], [peer, "check", *inputs]))
    data = os.path.join(HERE, "data", "ibm7545")
    thesis = ["--robot", f"{data}/robot.txt", "--env", f"{data}/environment.txt",
              "--path", f"{data}/path.txt", "--tolerance", "0.5"]
    cases.append(("thesis sample (IBM 7545, environment.txt, path.txt, Delta 0.5 in.)",
                  [grpvss, "verify", *thesis, "--quiet"], [peer, "check", *thesis]))
    return cases


def processes_table(build, runs):
    with tempfile.TemporaryDirectory() as work:
        cases = process_cases(build, work)
        print(f"# whole processes, {runs} interleaved runs ({load_text()})", file=sys.stderr)
        samples = {}
        for case, verify, peer in cases:
            warm = os.path.join(work, "cache-" + str(len(samples)))
            run_process(verify + ["--cache-dir", warm])
            variants = {"cold": verify + ["--no-cache"], "warm": verify + ["--cache-dir", warm],
                        "fcl": peer}
            samples[case] = {name: [] for name in variants}
            for _ in range(runs):
                for name, command in variants.items():
                    samples[case][name].append(run_process(command))
    print("| inputs | `grpvss verify` cold (--no-cache) | warm (cache hit) | FCL peer, Delta/4 "
          "| FCL / cold | FCL / warm | exit codes (cold, warm, FCL) |")
    print("|---|---|---|---|---|---|---|")
    for case, variants in samples.items():
        m = {name: statistics.median(s[1] for s in values) * 1000 for name, values in variants.items()}
        e = {name: statistics.median(s[0] for s in values) * 1000 for name, values in variants.items()}
        codes = ", ".join(str(values[0][2]) for values in variants.values())
        print(f"| {case} | {m['cold']:.1f} ms CPU ({e['cold']:.1f} elapsed) | {m['warm']:.1f} ms "
              f"({e['warm']:.1f}) | {m['fcl']:.1f} ms ({e['fcl']:.1f}) | {m['fcl'] / m['cold']:.2f}x "
              f"| {m['fcl'] / m['warm']:.2f}x | {codes} |")
    return samples


def targets(table):
    print("| target | measured | met |")
    print("|---|---|---|")
    for name, what in (("CheckGrpvss", "certified verdict"), ("Grpvss", "certified clearances")):
        per_config = cpu(table, f"BM_RobotConfiguration{name}/0/100")
        if per_config:
            print(f"| UR5e among 100 obstacles <= 5 us per configuration ({what}) "
                  f"| {per_config / 64:.2f} us | {'yes' if per_config / 64 <= 5 else 'no'} |")
    for delta in (1, 5):
        ours = cpu(table, f"BM_RobotTrajectoryGrpvss/0/100/100/{delta}")
        sampled = cpu(table, f"BM_RobotTrajectoryFclSampled/0/100/100/{delta}")
        ca = cpu(table, f"BM_RobotTrajectoryFclConservativeAdvancement/0/100/100/5")
        if ours and sampled:
            print(f"| UR5e 100 waypoints, Delta {delta} mm: >= 5x faster than FCL at Delta/4 "
                  f"| {sampled / ours:.2f}x | {'yes' if sampled / ours >= 5 else 'no'} |")
        if ours and ca:
            print(f"| UR5e 100 waypoints, Delta {delta} mm: >= 20x faster than FCL CA "
                  f"| {ca / ours:.2f}x | {'yes' if ca / ours >= 20 else 'no'} |")
    batch = cpu(table, "BM_RobotTrajectoryGrpvss/0/100/10/5")
    if batch:
        print(f"| warm: >= 1,000 certified 10-segment UR5e programs/s/core | {1e6 / batch:.0f} /s "
              f"| {'yes' if 1e6 / batch >= 1000 else 'no'} |")
    for name in ("BM_VerifyCpOperation/0", "BM_VerifyCpOperationThroughAPost/0"):
        value = cpu(table, name)
        if value:
            print(f"| Table 3 CP operation <= 57 us (`{name}`) | {value:.1f} us "
                  f"| {'yes' if value <= 57 else 'no'} |")


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--build", default=os.path.join(HERE, "build"))
    parser.add_argument("--repetitions", type=int, default=5)
    parser.add_argument("--runs", type=int, default=10)
    parser.add_argument("--json")
    parser.add_argument("--filter", default=DEFAULT_FILTER)
    parser.add_argument("--no-processes", action="store_true")
    parser.add_argument("--cpu", type=int)
    args = parser.parse_args()
    if args.cpu is not None:
        os.sched_setaffinity(0, {args.cpu})  # inherited by every process the script starts
    pinning = f", pinned to CPU {args.cpu}" if args.cpu is not None else ""
    print(f"# {load_text()}, nproc {os.cpu_count()}{pinning}")
    table = medians(run_benchmarks(args.build, args.repetitions, args.json, args.filter))
    print("\n## Per configuration (CPU medians; 64 configurations along a clear trajectory)\n")
    configuration_table(table)
    print("\n## Per trajectory (CPU medians)\n")
    trajectory_table(table)
    print("\n## Misses (50 random 3-segment UR5e PTP programs, 100 obstacles)\n")
    misses_table(table)
    if not args.no_processes:
        print("\n## Whole processes (CPU medians)\n")
        processes_table(args.build, args.runs)
    print("\n## Targets (issue #22 point 2)\n")
    targets(table)
    print(f"\n# done ({load_text()})")


if __name__ == "__main__":
    main()

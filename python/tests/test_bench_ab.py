"""scripts/bench-ab.py against fake benchmark binaries: the paired mode's ratios, its
alternating order, and why it exists (a machine whose speed steps between runs)."""
import importlib.util
import os
import stat
import sys

import pytest

from conftest import SOURCE_DIR

# A stand-in for grpvss_bench: lists BM_Small and BM_Large, and reports for the filtered ones a
# CPU time of base * (slow-down once this is the N-th call or later), logging each call.
FAKE = """#!{python}
import json, re, sys
args = dict(a.split("=", 1) for a in sys.argv[1:] if "=" in a)
names = [n for n in ("BM_Small", "BM_Large") if re.search(args["--benchmark_filter"], n)]
if "--benchmark_list_tests" in sys.argv:
    print("\\n".join(names))
    sys.exit(0)
with open({log!r}, "a+") as log:
    log.seek(0)
    calls = len(log.read().splitlines())
    log.write({label!r} + " " + args["--benchmark_filter"] + "\\n")
slow = {slow_down} if calls >= {slow_from} else 1.0
base = {{"BM_Small": {base} * 1.0, "BM_Large": {base} * 10.0}}
out = [{{"name": n, "cpu_time": base[n] * slow, "time_unit": "us"}} for n in names]
json.dump({{"benchmarks": out}}, open(args["--benchmark_out"], "w"))
"""


def load_script():
    spec = importlib.util.spec_from_file_location("bench_ab", SOURCE_DIR / "scripts" / "bench-ab.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def fake_binaries(tmp_path, slow_down=1.0, slow_from=0):
    log = tmp_path / "calls.log"
    binaries = {}
    for label, base in (("A", 100.0), ("B", 90.0)):
        path = tmp_path / f"bench_{label}"
        path.write_text(FAKE.format(python=sys.executable, log=str(log), label=label, base=base,
                                    slow_down=slow_down, slow_from=slow_from))
        path.chmod(path.stat().st_mode | stat.S_IXUSR)
        binaries[label] = str(path)
    return binaries, log


def test_pairs_run_each_benchmark_alone_and_alternate_which_binary_goes_first(tmp_path):
    bench_ab = load_script()
    binaries, log = fake_binaries(tmp_path)
    names = bench_ab.listed_benchmarks(binaries["B"], "BM_")
    assert names == ["BM_Small", "BM_Large"]
    samples, ratios = bench_ab.paired_samples(binaries, names, rounds=3, min_time="0.01")
    assert log.read_text().splitlines() == [
        "A ^BM_Small$", "B ^BM_Small$", "B ^BM_Small$", "A ^BM_Small$", "A ^BM_Small$", "B ^BM_Small$",
        "A ^BM_Large$", "B ^BM_Large$", "B ^BM_Large$", "A ^BM_Large$", "A ^BM_Large$", "B ^BM_Large$"]
    assert samples["A"] == {"BM_Small": [100.0] * 3, "BM_Large": [1000.0] * 3}
    assert samples["B"] == {"BM_Small": [90.0] * 3, "BM_Large": [900.0] * 3}
    assert ratios == {"BM_Small": [0.9] * 3, "BM_Large": [0.9] * 3}
    assert bench_ab.table(samples, ratios, "base").splitlines() == [
        "| benchmark | A: base | B: now | B / A | pairs B / A |",
        "|---|---|---|---|---|",
        "| `BM_Small` | 100.0 us (100.0-100.0) | 90.0 us (90.0-90.0) | 0.900 | 0.900 (0.900-0.900) |",
        "| `BM_Large` | 1000.0 us (1000.0-1000.0) | 900.0 us (900.0-900.0) | 0.900 | 0.900 (0.900-0.900) |"]


def test_a_machine_that_slows_down_between_runs_biases_rounds_but_not_pairs(tmp_path):
    # The machine runs 3x slower from the 4th call on (a vCPU that changed speed). Whole-binary
    # rounds (A B, B A, A B) give A calls 0, 3, 4 and B calls 1, 2, 5: two of A's runs are
    # slow, one of B's, and the medians say B is 3x faster than it is.
    bench_ab = load_script()
    (tmp_path / "rounds").mkdir()
    binaries, _ = fake_binaries(tmp_path / "rounds", slow_down=3.0, slow_from=3)
    rounds = bench_ab.interleaved_samples(binaries, "BM_Small", rounds=3, min_time="0.01")
    assert rounds["A"]["BM_Small"] == [100.0, 300.0, 300.0]
    assert rounds["B"]["BM_Small"] == [90.0, 90.0, 270.0]
    assert bench_ab.table(rounds, None, "base").splitlines()[2].endswith("| 0.300 |")

    # Pairs: only the pair (B call 2, A call 3) straddles the step, so one ratio is off and
    # their median is the true 0.9.
    (tmp_path / "pairs").mkdir()
    binaries, _ = fake_binaries(tmp_path / "pairs", slow_down=3.0, slow_from=3)
    samples, ratios = bench_ab.paired_samples(binaries, ["BM_Small"], rounds=5, min_time="0.01")
    assert ratios["BM_Small"] == pytest.approx([0.9, 0.3, 0.9, 0.9, 0.9])
    assert bench_ab.table(samples, ratios, "base").splitlines()[2].endswith("| 0.900 (0.300-0.900) |")


def test_pinning_names_one_cpu_and_none_leaves_the_child_alone():
    bench_ab = load_script()
    assert bench_ab.pinned_to(None) is None
    cpu = min(os.sched_getaffinity(0))
    pin = bench_ab.pinned_to(cpu)
    before = os.sched_getaffinity(0)
    try:
        pin()
        assert os.sched_getaffinity(0) == {cpu}
    finally:
        os.sched_setaffinity(0, before)

"""Shared fixtures: the source tree, the built `grpvss` CLI (GRPVSS_CLI, set by ctest) and a
helper that runs it and returns its exit code and outputs, to compare the module with."""
import json
import os
import pathlib
import subprocess
import threading

import pytest

SOURCE_DIR = pathlib.Path(os.environ.get("GRPVSS_SOURCE_DIR",
                                         pathlib.Path(__file__).resolve().parents[2]))
DATA = SOURCE_DIR / "data" / "ibm7545"
ROBOT = str(DATA / "robot.txt")
ENVIRONMENT = str(DATA / "environment.txt")
PATH = str(DATA / "path.txt")


def cli_path():
    cli = os.environ.get("GRPVSS_CLI", str(SOURCE_DIR / "build" / "grpvss"))
    assert os.access(cli, os.X_OK), f"the grpvss CLI is not built at {cli} (set GRPVSS_CLI)"
    return cli


def run_cli(*args):
    """Runs `grpvss ARGS`; returns the CompletedProcess (text)."""
    return subprocess.run([cli_path(), *args], capture_output=True, text=True, check=False)


def cli_verify(tmp_path, robot, environment, path, tolerance, *options):
    """`grpvss verify --json --certificate` (certificate only in certified mode): returns
    (exit code, report text, certificate text or None)."""
    report = tmp_path / "report.json"
    certificate = tmp_path / "certificate.json"
    args = ["verify", "--robot", robot, "--env", environment, "--path", path,
            "--tolerance", repr(tolerance), "--json", str(report), "--quiet", "--force", *options]
    thesis = "thesis" in options
    if not thesis:
        args += ["--certificate", str(certificate)]
    completed = run_cli(*args)
    assert completed.returncode in (0, 1, 3, 4, 5), completed.stderr
    return (completed.returncode, report.read_text(),
            None if thesis else certificate.read_text())


def pinned(report_text):
    """The report with its one varying field, generated_at, replaced by ''."""
    document = json.loads(report_text)
    document["generated_at"] = ""
    return document


@pytest.fixture
def sample_paths():
    return ROBOT, ENVIRONMENT, PATH


def run_in_two_threads_at_once(verify):
    """[verify(0), verify(1)], each in its own thread. Each verification waits (with the GIL
    released) until two are active: they can only meet if the GIL is released; otherwise the
    first times out alone and the peak stays 1. Asserts that both ran at once, and that no
    thread raised (an exception is never lost in the thread)."""
    import _grpvss  # the extension, found through PYTHONPATH like the tests' own imports

    results, errors = [None, None], []

    def work(index):
        try:
            results[index] = verify(index)
        except Exception as error:
            errors.append(error)

    _grpvss._reset_activity(rendezvous=2)
    try:
        threads = [threading.Thread(target=work, args=(i,)) for i in range(2)]
        for thread in threads:
            thread.start()
        for thread in threads:
            thread.join()
        active, peak = _grpvss._activity()
    finally:
        _grpvss._reset_activity(rendezvous=0)
    assert not errors
    assert (active, peak) == (0, 2)
    return results

"""Python threads verify in parallel (the GIL is released while a path is verified) against
one shared cell, with the results of a sequential run."""
import threading

import grpvss
from conftest import DATA, ROBOT, run_in_two_threads_at_once

JOBS = [(str(DATA / "environment.txt"), str(DATA / "path.txt")),
        (str(DATA / "bench-environment.txt"), str(DATA / "path-output-sample.txt"))]


def test_two_threads_overlap_and_agree_with_a_sequential_run():
    sessions = [grpvss.VerificationSession(ROBOT, environment, 0.5) for environment, _ in JOBS]
    sequential = [s.verify(path).json_report("t") for s, (_, path) in zip(sessions, JOBS)]
    results = run_in_two_threads_at_once(lambda i: sessions[i].verify(JOBS[i][1]).json_report("t"))
    assert results == sequential


def test_threads_share_one_session():
    session = grpvss.VerificationSession(ROBOT, str(DATA / "environment.txt"), 0.5)
    reference = session.verify(str(DATA / "path.txt")).json_report("t")
    outputs = []
    lock = threading.Lock()

    def work():
        text = session.verify(str(DATA / "path.txt")).json_report("t")
        with lock:
            outputs.append(text)

    threads = [threading.Thread(target=work) for _ in range(4)]
    for thread in threads:
        thread.start()
    for thread in threads:
        thread.join()
    assert outputs == [reference] * 4

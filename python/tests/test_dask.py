"""grpvss.dask.verify_batch on a LocalCluster of 2 worker processes: 105 jobs (the thesis
sample paths and a PTP operation, five environments, seven tolerances, both timings) give the
results of the single-process loop, and each worker builds a cell once per distinct set-up;
8 cell jobs with trajectories and robot programs give the single-process results and the
certificates `grpvss batch` writes."""
import hashlib
import json
import pathlib

import distributed
import pytest

import grpvss
import grpvss.dask
from conftest import DATA, ROBOT, run_cli

HERE = pathlib.Path(__file__).parent
ENVIRONMENTS = ["environment", "bench-environment", "bench-environment-cp-line",
                "bench-environment-near-miss", "bench-environment-within-tolerance"]
PATHS = [str(DATA / "path.txt"), str(DATA / "path-output-sample.txt"),
         str(HERE / "data" / "ptp-operation.txt")]
TOLERANCES = [0.1, 0.25, 0.5, 0.6, 0.7, 1.0, 2.0]


def jobs():
    batch = []
    for environment in ENVIRONMENTS:
        for tolerance in TOLERANCES:
            for path in PATHS:
                timing = "synchronized" if len(batch) % 2 else "independent"
                batch.append(grpvss.dask.Job(ROBOT, str(DATA / f"{environment}.txt"), path,
                                             tolerance, timing=timing))
    return batch


@pytest.fixture(scope="module")
def client():
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                  host="127.0.0.1", dashboard_address=None) as cluster:
        with distributed.Client(cluster) as dask_client:
            yield dask_client


def test_dask_batch_equals_the_single_process_loop(client):
    batch = jobs()
    assert len(batch) == 105
    on_dask = grpvss.dask.verify_batch(client, batch)
    local = grpvss.dask.verify_local(batch)
    assert on_dask == local
    assert {s["verdict"] for s in local} == {"CLEAR", "COLLISION", "WITHIN_TOLERANCE", "ERROR"}
    # Each worker process built each distinct cell at most once, and both did work.
    distinct = len({job.cell_key() for job in batch})
    assert distinct == 35
    caches = client.run(grpvss.dask.cache_info)
    assert len(caches) == 2
    for cache in caches.values():
        assert 1 <= cache["built"] == cache["cells"] <= distinct
    assert distinct <= sum(cache["built"] for cache in caches.values()) <= 2 * distinct


def test_jobs_as_dicts_and_an_empty_batch(client):
    job = {"robot": ROBOT, "environment": str(DATA / "environment.txt"),
           "path": str(DATA / "path.txt"), "tolerance": 0.5}
    [summary] = grpvss.dask.verify_batch(client, [job])
    assert (summary["verdict"], summary["exit_code"], summary["step_count"]) == ("COLLISION", 1, 23)
    assert grpvss.dask.verify_batch(client, []) == []


CELL = str(pathlib.Path(__file__).resolve().parents[2] / "tests" / "data" / "cells" /
           "ur5e-post-no-self.yaml")
MOTIONS = pathlib.Path(__file__).resolve().parents[2] / "tests" / "data"
CELL_MOTIONS = [("trajectory", "trajectories/ur5e-clear.json"),
                ("trajectory", "trajectories/ur5e-through-post.csv"),
                ("program", "programs/ur5e-clear.script"),
                ("program", "programs/ur5e-through-post.script")]


def test_trajectory_and_program_jobs_equal_the_single_process_and_cli_batch(client, tmp_path):
    """8 cell jobs (2 trajectories, 2 programs, the cell's tolerance and 0.01 m) on Dask give
    the single-process results, and the certificates `grpvss batch` writes for the same jobs."""
    batch, manifest = [], []
    for tolerance in (None, 0.01):
        for kind, motion in CELL_MOTIONS:
            batch.append(grpvss.dask.Job(cell=CELL, tolerance=tolerance,
                                         **{kind: str(MOTIONS / motion)}))
            line = {"cell": CELL, kind: str(MOTIONS / motion),
                    "certificate": str(tmp_path / f"{len(manifest)}.cert")}
            if tolerance is not None:
                line["tolerance"] = tolerance
            manifest.append(line)
    on_dask = grpvss.dask.verify_batch(client, batch, batch_size=2)
    local = grpvss.dask.verify_local(batch)
    assert on_dask == local
    assert [s["verdict"] for s in local] == ["CLEAR", "COLLISION"] * 4
    assert [s["motion_model"].split(" ")[0] for s in local[:4]] == \
        ["joint", "joint", "program", "program"]
    # The program's reader warning travels with its summary.
    assert any(line == 9 for _, line, _ in local[2]["warnings"])
    (tmp_path / "m.jsonl").write_text("".join(json.dumps(job) + "\n" for job in manifest))
    completed = run_cli("batch", str(tmp_path / "m.jsonl"))
    assert completed.returncode == 1, completed.stderr
    lines = [json.loads(line) for line in completed.stdout.splitlines()]
    for index, (summary, line) in enumerate(zip(local, lines)):
        assert (line["verdict"], line["steps"]) == (summary["verdict"], summary["step_count"])
        written = (tmp_path / f"{index}.cert").read_bytes()
        assert hashlib.sha256(written).hexdigest() == summary["certificate_sha256"], index


def test_a_job_gives_exactly_one_motion():
    with pytest.raises(grpvss.InputError) as raised:
        grpvss.dask.Job(cell=CELL, path="p.txt", program="p.script")
    assert raised.value.expected == "exactly one of path, trajectory and program"
    with pytest.raises(grpvss.InputError) as raised:
        grpvss.dask.Job(cell=CELL, program="p.script", timing="independent")
    assert raised.value.found == "timing"

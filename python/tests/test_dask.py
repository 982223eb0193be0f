"""grpvss.dask.verify_batch on a LocalCluster of 2 worker processes: 105 jobs (the thesis
sample paths and a PTP operation, five environments, seven tolerances, both timings) give the
results of the single-process loop, and each worker builds a cell once per distinct set-up."""
import pathlib

import distributed
import pytest

import grpvss
import grpvss.dask
from conftest import DATA, ROBOT

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
    assert (summary["verdict"], summary["exit_code"], summary["step_count"]) == ("COLLISION", 1, 37)
    assert grpvss.dask.verify_batch(client, []) == []

"""Batches of verifications on Dask distributed (docs/scale-out.md).

A job names its input files and options (:class:`Job`): its model (thesis ``robot`` and
``environment`` files, or a ``cell`` file) and its motion (a thesis ``path``, a planner's
``trajectory`` or a robot ``program``). :func:`verify_batch` runs the jobs on a
``distributed.Client``'s workers and returns one :func:`summarize` dict per job, in job
order. Each worker process builds the prepared cell (:class:`grpvss.VerificationSession`)
once per distinct model + tolerance + mode + offset and reuses it for every job that shares
them. The files must be readable on every worker under the same names.
:func:`verify_local` is the same batch in this process: the reference the Dask run matches.
"""
import dataclasses
import hashlib
import os
import threading

import grpvss


@dataclasses.dataclass(frozen=True)
class Job:
    """One verification, ``grpvss verify``'s inputs and options: ``robot`` and
    ``environment`` (thesis files) or ``cell``; exactly one of ``path``, ``trajectory`` and
    ``program``. Unset (None), ``tolerance``, ``timing`` and ``cp_speed`` are the model's (a
    cell's tolerance and CP speed and synchronized timing; a thesis robot's independent timing
    and CP speed 1). A trajectory or a program is the motion: ``timing`` and
    ``profile_table`` are refused with it (a program's timing may be "synchronized");
    ``start`` (joint values, rad) is a program's start, else the robot's home."""
    robot: str = None
    environment: str = None
    path: str = None
    tolerance: float = None
    mode: str = "certified"
    offset: str = "auto"
    timing: str = None
    cp_speed: float = None
    ik: str = "auto"
    profile_table: str = None
    cell: str = None
    trajectory: str = None
    program: str = None
    start: tuple = None
    claim: str = "motion"

    def __post_init__(self):
        motions = [key for key in ("path", "trajectory", "program") if getattr(self, key)]
        if len(motions) != 1:
            _refuse("exactly one of path, trajectory and program",
                    "neither" if not motions else ", ".join(motions))
        if bool(self.cell) == bool(self.robot or self.environment):
            _refuse("either cell, or robot with environment", "both" if self.cell else "neither")
        if not self.cell and not (self.robot and self.environment and self.tolerance):
            _refuse("robot, environment and tolerance (or a cell)", "a job without them")
        if self.trajectory or self.program:
            motion = "trajectory" if self.trajectory else "program"
            if self.timing not in (None, "synchronized") or (self.trajectory and self.timing):
                _refuse(f"no timing with {motion}", "timing")
            if self.profile_table:
                _refuse(f"no profile_table with {motion}", "profile_table")
        if self.start is not None and not self.program:
            _refuse("start only with a program", "start")

    def cell_key(self):
        """What the prepared cell depends on (the files by name and content)."""
        model = ((os.path.abspath(self.cell), _digest(self.cell)) if self.cell else
                 (os.path.abspath(self.robot), _digest(self.robot),
                  os.path.abspath(self.environment), _digest(self.environment)))
        tolerance = None if self.tolerance is None else float(self.tolerance)
        return model + (tolerance, self.mode, self.offset)


def _refuse(expected, found):
    raise grpvss.InputError(f"job:0: expected {expected}, found {found}", "job", 0, expected,
                            found)


def _digest(file):
    with open(file, "rb") as stream:
        return hashlib.sha256(stream.read()).hexdigest()


_sessions = {}
_sessions_lock = threading.Lock()
_built = 0


def _session_for(job):
    global _built
    key = job.cell_key()
    with _sessions_lock:
        session = _sessions.get(key)
        if session is None:
            if job.cell:
                session = grpvss.load_cell(job.cell).session(job.tolerance, mode=job.mode,
                                                             offset=job.offset)
            else:
                session = grpvss.VerificationSession(job.robot, job.environment, job.tolerance,
                                                     mode=job.mode, offset=job.offset)
            _sessions[key] = session
            _built += 1
        return session


def cache_info():
    """This process's cache: ``{"cells": cached cells, "built": cells built so far}``."""
    with _sessions_lock:
        return {"cells": len(_sessions), "built": _built}


def clear_cache():
    """Forgets this process's prepared cells."""
    global _built
    with _sessions_lock:
        _sessions.clear()
        _built = 0


def summarize(result):
    """A result as plain, picklable data: verdict, exit code, steps, motion model,
    clearances, episodes, errors, a program's reader warnings, and the SHA-256 of its JSON
    report (``generated_at`` blanked) and certificate."""
    certificate = result.certificate
    return {
        "verdict": result.verdict.name,
        "motion_model": result.motion_model,
        "warnings": [tuple(warning) for warning in result.warnings],
        "exit_code": result.exit_code,
        "step_count": result.step_count,
        "collision_step": result.collision_step,
        "total_cycle_time": result.total_cycle_time,
        "link_clearances": [(c.link, c.min_clearance, c.step, c.obstacle, c.min_motion_clearance)
                            for c in result.link_clearances],
        "episodes": [(e.link, e.hull, e.obstacle, e.first_step, e.last_step)
                     for e in result.episodes],
        "errors": [(e.code, e.segment, e.step, e.message) for e in result.errors],
        "report_sha256": hashlib.sha256(result.json_report(generated_at="").encode()).hexdigest(),
        "certificate_sha256": (hashlib.sha256(certificate.to_json().encode()).hexdigest()
                               if certificate is not None else None),
    }


def _as_job(job):
    return job if isinstance(job, Job) else Job(**job)


def run_job(job):
    """Verifies one job (a :class:`Job` or a dict of its fields) with this process's cached
    cell; returns :func:`summarize` of the result."""
    job = _as_job(job)
    session = _session_for(job)
    if job.program:
        result = session.verify_program(job.program, ik=job.ik, start=job.start, claim=job.claim)
    elif job.trajectory:
        result = session.verify_trajectory_file(job.trajectory, ik=job.ik, claim=job.claim)
    else:
        result = session.verify(job.path, timing=job.timing, cp_speed=job.cp_speed, ik=job.ik,
                                profile_table=job.profile_table, claim=job.claim)
    return summarize(result)


def verify_local(jobs):
    """The batch in this process, one job after the other."""
    return [run_job(job) for job in jobs]


def verify_batch(client, jobs, batch_size=None):
    """Runs ``jobs`` on the workers of ``client`` (a ``distributed.Client``); returns one
    :func:`summarize` dict per job, in job order. ``batch_size`` jobs go to a worker as one
    task (default: about 4 tasks per worker thread), so that the cells are reused."""
    jobs = [_as_job(job) for job in jobs]
    if not jobs:
        return []
    if batch_size is None:
        threads = sum(client.nthreads().values()) or 1
        batch_size = max(1, len(jobs) // (4 * threads))
    chunks = [jobs[i:i + batch_size] for i in range(0, len(jobs), batch_size)]
    futures = client.map(verify_local, chunks, pure=False)
    return [summary for chunk in client.gather(futures) for summary in chunk]

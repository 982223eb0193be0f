"""Joint trajectories from Python against `grpvss verify|check-certificate --trajectory` on the
UR5e cell tests/data/cells/ur5e-post-no-self.yaml (the robot of ../shared/robots, tests only):
numpy arrays give the CLI's verdict, step count, JSON report and certificate on the same data
written to CSV (their canonical CSV text, pinned here), a trajectory file gives the CLI's
certificate byte for byte, check_certificate re-derives the trajectory from the arrays or the
file and rejects other data, errors raise grpvss.InputError naming the argument or the line,
and two threads verify trajectories at once (the GIL released)."""
import json
import subprocess

import numpy
import pytest

import grpvss
from conftest import SOURCE_DIR, cli_path, run_cli, run_in_two_threads_at_once

CELL = str(SOURCE_DIR / "tests" / "data" / "cells" / "ur5e-post-no-self.yaml")
TRAJECTORIES = SOURCE_DIR / "tests" / "data" / "trajectories"

# tests/data/trajectories/ur5e-through-post.csv: linear, the forearm hits the post.
THROUGH_POST_TIMES = numpy.array([0.0, 1.0, 2.0])
THROUGH_POST = numpy.array([[0.0, -1.5708, 1.5708, 0.0, 0.0, 0.0],
                            [0.8, -1.5708, 1.5708, 0.0, 0.0, 0.0],
                            [1.74533, -1.5708, 1.5708, 0.0, 0.0, 0.0]])
# tests/data/trajectories/ur5e-clear.json: cubic Hermite, columns in the file's joint order.
CLEAR_NAMES = ["shoulder_lift_joint", "shoulder_pan_joint", "elbow_joint", "wrist_1_joint",
               "wrist_2_joint", "wrist_3_joint"]
CLEAR_TIMES = numpy.array([0.0, 1.5, 3.0])
CLEAR_POSITIONS = numpy.array([[-1.5708, 0, 1.5708, 0, 0, 0], [-1.4, -0.3, 1.4, 0, 0, 0],
                               [-1.3, -0.5236, 1.3, 0, 0, 0]])
CLEAR_VELOCITIES = numpy.array([[0, 0, 0, 0, 0, 0], [0.1, -0.3, -0.1, 0, 0, 0],
                                [0, 0, 0, 0, 0, 0]], dtype=float)


@pytest.fixture(scope="module")
def cell():
    return grpvss.load_cell(CELL)


def cli_verify_trajectory(folder, trajectory):
    """`grpvss verify --cell --trajectory --json --certificate` run in `folder` (so that a
    trajectory there is named as the arrays' label): (exit code, summary, report, certificate
    text)."""
    report, certificate = folder / "cli.json", folder / "cli.cert"
    completed = subprocess.run(
        [cli_path(), "verify", "--cell", CELL, "--trajectory", str(trajectory), "--json",
         str(report), "--certificate", str(certificate), "--force", "--no-cache"],
        cwd=folder, capture_output=True, text=True, check=False)
    assert completed.returncode in (0, 1), completed.stderr
    return completed.returncode, completed.stdout, report.read_text(), certificate.read_text()


def summary_steps(summary):
    return int(summary.split("steps: ")[1].split()[0])


def test_the_canonical_csv_of_arrays_is_the_shortest_round_trip_text(cell):
    trajectory = grpvss.joint_trajectory(cell.robot, THROUGH_POST_TIMES, THROUGH_POST)
    assert trajectory.to_csv() == (
        "time,shoulder_pan_joint,shoulder_lift_joint,elbow_joint,wrist_1_joint,wrist_2_joint,"
        "wrist_3_joint\n"
        "0,0,-1.5708,1.5708,0,0,0\n"
        "1,0.8,-1.5708,1.5708,0,0,0\n"
        "2,1.74533,-1.5708,1.5708,0,0,0\n")
    # The same bytes as the test data file: the same digest, so the same certificate.
    assert trajectory.to_csv() == (TRAJECTORIES / "ur5e-through-post.csv").read_text()
    assert trajectory.interpolation == "linear"
    assert trajectory.waypoint_times == [0.0, 1.0, 2.0]
    cubic = grpvss.joint_trajectory(cell.robot, CLEAR_TIMES, CLEAR_POSITIONS, CLEAR_VELOCITIES,
                                    joint_names=CLEAR_NAMES)
    assert cubic.to_csv().splitlines()[0] == (
        "time," + ",".join(CLEAR_NAMES) + "," + ",".join(n + ".vel" for n in CLEAR_NAMES))
    assert cubic.to_csv().splitlines()[2] == "1.5,-1.4,-0.3,1.4,0,0,0,0.1,-0.3,-0.1,0,0,0"
    assert cubic.interpolation == "cubic-hermite"


@pytest.mark.parametrize("arrays,verdict,steps", [
    ((THROUGH_POST_TIMES, THROUGH_POST, None, None), "COLLISION", 34),
    ((CLEAR_TIMES, CLEAR_POSITIONS, CLEAR_VELOCITIES, CLEAR_NAMES), "CLEAR", 6)])
def test_arrays_verify_as_the_cli_verifies_their_csv(tmp_path, cell, arrays, verdict, steps):
    times, positions, velocities, names = arrays
    result = cell.verify_trajectory(times, positions, velocities=velocities, joint_names=names)
    result.trajectory.save(str(tmp_path / grpvss.ARRAYS_LABEL))
    code, summary, report, certificate = cli_verify_trajectory(tmp_path, grpvss.ARRAYS_LABEL)
    assert result.verdict.name == verdict == json.loads(report)["verdict"]
    assert result.exit_code == code
    assert result.step_count == steps == summary_steps(summary)
    assert result.certificate.to_json() == certificate
    generated_at = json.loads(report)["generated_at"]
    assert result.json_report(generated_at=generated_at) == report
    assert result.motion_model == json.loads(report)["motion_model"]
    assert result.path is None
    # Per-link clearances and episodes with names, as for paths.
    assert result.clearances.shape == (steps, cell.robot.link_count)
    if verdict == "COLLISION":
        named = {(cell.robot.link_names[e.link], cell.environment.obstacle_names[e.obstacle])
                 for e in result.episodes}
        assert ("forearm_link", "post") in named


def test_a_trajectory_file_verifies_as_the_cli_verifies_it(tmp_path, cell):
    file = TRAJECTORIES / "ur5e-clear.json"
    code, summary, report, certificate = cli_verify_trajectory(tmp_path, file)
    result = cell.verify_trajectory_file(str(file))
    assert (result.exit_code, result.step_count) == (code, summary_steps(summary)) == (0, 6)
    assert result.certificate.to_json() == certificate
    # The arrays of the same data differ only in the digest of what was verified.
    arrays = cell.verify_trajectory(CLEAR_TIMES, CLEAR_POSITIONS, CLEAR_VELOCITIES, CLEAR_NAMES)
    from_file, from_arrays = json.loads(certificate), json.loads(arrays.certificate.to_json())
    assert from_file["inputs"]["trajectory"] != from_arrays["inputs"]["trajectory"]
    from_arrays["inputs"]["trajectory"] = from_file["inputs"]["trajectory"]
    assert from_arrays == from_file


def test_check_certificate_re_derives_the_trajectory(tmp_path, cell):
    result = cell.verify_trajectory(CLEAR_TIMES, CLEAR_POSITIONS, CLEAR_VELOCITIES, CLEAR_NAMES)
    check = cell.check_trajectory_certificate(result.trajectory, result.certificate)
    assert check.accepted, check.messages
    assert check.claim.name == "CLEAR"
    # The same arrays again, and the CLI on their CSV: the same decision.
    again = grpvss.joint_trajectory(cell.robot, CLEAR_TIMES, CLEAR_POSITIONS, CLEAR_VELOCITIES,
                                    joint_names=CLEAR_NAMES)
    assert grpvss.check_certificate(cell.robot, cell.environment, again,
                                    result.certificate).accepted
    result.trajectory.save(str(tmp_path / "t.csv"))
    result.certificate.save(str(tmp_path / "c.json"))
    completed = run_cli("check-certificate", "--cell", CELL, "--trajectory",
                        str(tmp_path / "t.csv"), "--json", str(tmp_path / "c.json"))
    assert completed.returncode == 0, completed.stdout + completed.stderr
    assert json.loads(completed.stdout)["inequalities_checked"] == check.inequalities_checked
    # Other arrays: another digest, rejected.
    other = grpvss.joint_trajectory(cell.robot, CLEAR_TIMES, CLEAR_POSITIONS + 0.001,
                                    CLEAR_VELOCITIES, joint_names=CLEAR_NAMES)
    rejected = cell.check_trajectory_certificate(other, result.certificate)
    assert not rejected.accepted
    assert any("trajectory" in message for message in rejected.messages), rejected.messages
    # A file: read as the CLI reads it.
    file_result = cell.verify_trajectory_file(str(TRAJECTORIES / "ur5e-clear.json"))
    assert cell.check_trajectory_certificate(str(TRAJECTORIES / "ur5e-clear.json"),
                                             file_result.certificate).accepted
    with pytest.raises(grpvss.InputError) as raised:
        cell.check_certificate(result.trajectory, result.certificate, timing="synchronized")
    assert raised.value.file == "timing"


def error_of(call):
    with pytest.raises(grpvss.InputError) as raised:
        call()
    return raised.value


def test_bad_arrays_raise_input_errors_naming_the_argument_or_the_line(cell):
    times, positions = THROUGH_POST_TIMES, THROUGH_POST
    error = error_of(lambda: cell.verify_trajectory(times, positions[:, :5]))
    assert (error.file, error.line, error.found) == ("positions", 0, "shape (3, 5)")
    assert error.expected == ("an array of shape (3, 6) (N waypoints from times, J joints "
                              "from joint_names)")
    error = error_of(lambda: cell.verify_trajectory(times.reshape(3, 1), positions))
    assert (error.file, error.found) == ("times", "shape (3, 1)")
    error = error_of(lambda: cell.verify_trajectory(times, positions, velocities=positions[:2]))
    assert (error.file, error.found) == ("velocities", "shape (2, 6)")
    # times[2] is line 4 of the CSV form.
    error = error_of(lambda: cell.verify_trajectory([0.0, 1.0, 1.0], positions))
    assert (error.file, error.line) == (grpvss.ARRAYS_LABEL, 4)
    names = ["shoulder_pan_joint", "shoulder_lift_joint", "elbow_joint", "wrist_1_joint",
             "wrist_2_joint", "gripper_joint"]
    error = error_of(lambda: cell.verify_trajectory(times, positions, joint_names=names))
    assert (error.file, error.line) == (grpvss.ARRAYS_LABEL, 1)
    assert error.found == "missing wrist_3_joint; extra gripper_joint"
    # The elbow leaves its limit (pi) in piece 2, which starts at times[1] (line 3).
    elbow = numpy.array([[0, -1.5708, 1.5708, 0, 0, 0], [0, -1.5708, 2.5, 0, 0, 0],
                         [0, -1.5708, 3.3, 0, 0, 0]])
    error = error_of(lambda: cell.verify_trajectory([0.0, 1.0, 3.0], elbow, label="elbow.csv"))
    assert (error.file, error.line) == ("elbow.csv", 3)
    assert error.found == ("joint 'elbow_joint' (3) is above its upper position limit "
                           "3.141592653589793 at t = 3 s: 3.3 (piece 2, between line 3 and "
                           "line 4)")
    error = error_of(lambda: cell.verify_trajectory(times, positions, mode="thesis"))
    assert (error.file, error.found) == ("mode", "thesis")
    error = error_of(lambda: cell.verify_trajectory_file(str(TRAJECTORIES / "ur5e-names-mismatch.csv")))
    assert (error.file, error.line) == (str(TRAJECTORIES / "ur5e-names-mismatch.csv"), 1)


def test_two_threads_verify_trajectories_at_once(cell):
    session = cell.session()
    reference = session.verify_trajectory(THROUGH_POST_TIMES, THROUGH_POST).json_report("t")
    results = run_in_two_threads_at_once(
        lambda i: session.verify_trajectory(THROUGH_POST_TIMES, THROUGH_POST).json_report("t"))
    assert results == [reference, reference]

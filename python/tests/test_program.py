"""Robot programs from Python against `grpvss verify|check-certificate --program` on the UR5e
cell tests/data/cells/ur5e-post-no-self.yaml (the robot of ../shared/robots, tests only) with
the programs of tests/data/programs: Cell.verify_program gives the CLI's verdict, step count,
motion model, JSON report and certificate bytes; the reader's warnings the CLI prints are
result.warnings as (file, line, text); the IK resolves the pose back to the joints it was
computed from; a collision's episodes name the forearm and the post; check_certificate
accepts the program's certificate (and the CLI accepts the one Python wrote), rejects it for
an edited program; a refused motion raises InputError with the file and line the CLI names;
two threads verify programs at once (the GIL released)."""
import json
import subprocess

import numpy
import pytest

import grpvss
from conftest import SOURCE_DIR, cli_path, run_cli, run_in_two_threads_at_once

CELL = str(SOURCE_DIR / "tests" / "data" / "cells" / "ur5e-post-no-self.yaml")
PROGRAMS = SOURCE_DIR / "tests" / "data" / "programs"


@pytest.fixture(scope="module")
def cell():
    return grpvss.load_cell(CELL)


def cli_verify_program(folder, program):
    """`grpvss verify --cell --program --json --certificate`: (exit code, stdout, stderr,
    report, certificate text)."""
    report, certificate = folder / "cli.json", folder / "cli.cert"
    completed = subprocess.run(
        [cli_path(), "verify", "--cell", CELL, "--program", str(program), "--json", str(report),
         "--certificate", str(certificate), "--force", "--no-cache"],
        capture_output=True, text=True, check=False)
    assert completed.returncode in (0, 1), completed.stderr
    return (completed.returncode, completed.stdout, completed.stderr, report.read_text(),
            certificate.read_text())


def summary_steps(summary):
    return int(summary.split("steps: ")[1].split()[0])


@pytest.mark.parametrize("name,verdict", [("ur5e-clear.script", "CLEAR"),
                                          ("ur5e-through-post.script", "COLLISION")])
def test_a_program_verifies_as_the_cli_verifies_it(tmp_path, cell, name, verdict):
    file = str(PROGRAMS / name)
    code, out, err, report, certificate = cli_verify_program(tmp_path, file)
    result = cell.verify_program(file)
    assert result.verdict.name == verdict == json.loads(report)["verdict"]
    assert result.exit_code == code
    assert result.step_count == summary_steps(out)
    assert result.motion_model == json.loads(report)["motion_model"]
    assert result.motion_model.startswith(f"program {name} (URScript), synchronized PTP")
    assert f"motion: {result.motion_model}\n" in out
    assert result.certificate.to_json() == certificate
    generated_at = json.loads(report)["generated_at"]
    assert result.json_report(generated_at=generated_at) == report
    assert result.path is None and result.trajectory is None
    assert result.program.file == file
    # Each warning the CLI prints is one of the result's, as data.
    printed = [line for line in err.splitlines() if line.startswith("warning: ")]
    assert printed == [f"warning: {f}:{line}: {text}" for f, line, text in result.warnings]
    if verdict == "COLLISION":
        named = {(cell.robot.link_names[e.link], cell.environment.obstacle_names[e.obstacle])
                 for e in result.episodes}
        assert ("forearm_link", "post") in named


def test_a_programs_claim_is_that_of_verify_program(cell, tmp_path):
    # The default claim holds the tolerance along the motion (12 steps); `steps` is
    # `grpvss verify --program --claim steps` (10 steps), certificate and all.
    motion = cell.verify_program(PROGRAMS / "ur5e-clear.script")
    steps = cell.verify_program(PROGRAMS / "ur5e-clear.script", claim="steps")
    assert (motion.step_count, steps.step_count) == (12, 10)
    completed = run_cli("verify", "--cell", CELL, "--program", str(PROGRAMS / "ur5e-clear.script"),
                        "--claim", "steps", "--certificate", str(tmp_path / "c.cert"))
    assert completed.returncode == 0, completed.stderr
    assert summary_steps(completed.stdout) == 10
    assert json.loads((tmp_path / "c.cert").read_text())["clear_claim"] == "steps"


def test_the_reader_warning_and_the_pose_solved_by_ik(cell):
    result = cell.verify_program(PROGRAMS / "ur5e-clear.script")
    assert result.verdict == grpvss.Verdict.CLEAR
    assert result.step_count == 12
    assert (str(PROGRAMS / "ur5e-clear.script"), 9, 'not read: popup("placed")') in result.warnings
    targets = result.program.targets
    assert [(line, cartesian) for _, line, cartesian, _ in targets] == \
        [(7, False), (8, True), (10, False)]
    # The pose was computed from these joints with the UR5e's published DH parameters
    # (6 decimals written): the IK in the cell finds them back.
    numpy.testing.assert_allclose(targets[1][3], [-0.6, -1.4, 1.5, -1.2, -1.57, 0.2], atol=5e-6)
    assert targets[0][3][0] == -0.5235987755982988
    assert result.program.language == "URScript"
    assert json.loads(result.certificate.to_json())["inputs"]["program"] == result.program.digest


def test_check_certificate_accepts_the_programs_certificate(tmp_path, cell):
    file = PROGRAMS / "ur5e-clear.script"
    result = cell.verify_program(file)
    check = cell.check_program_certificate(result.program, result.certificate)
    assert check.accepted, check.messages
    assert check.claim.name == "CLEAR"
    assert grpvss.check_certificate(cell.robot, cell.environment, result.program,
                                    result.certificate).accepted
    # The CLI accepts the certificate Python wrote, deciding as many inequalities.
    result.certificate.save(str(tmp_path / "c.json"))
    completed = run_cli("check-certificate", "--cell", CELL, "--program", str(file), "--json",
                        str(tmp_path / "c.json"))
    assert completed.returncode == 0, completed.stdout + completed.stderr
    assert json.loads(completed.stdout)["inequalities_checked"] == check.inequalities_checked
    # An edited program (another target): another digest, rejected.
    edited = tmp_path / "edited.script"
    edited.write_text(file.read_text().replace("movej([0, -1.5707963267948966",
                                               "movej([0.1, -1.5707963267948966"))
    rejected = cell.check_program_certificate(str(edited), result.certificate)
    assert not rejected.accepted
    assert rejected.exit_code == 1
    with pytest.raises(grpvss.InputError) as raised:
        cell.check_certificate(result.program, result.certificate, timing="independent")
    assert raised.value.file == "timing"


def test_a_refused_motion_raises_input_error_with_the_clis_file_and_line(cell):
    file = str(PROGRAMS / "ur5e-movel.script")
    completed = run_cli("verify", "--cell", CELL, "--program", file, "--quiet")
    assert completed.returncode == 2
    with pytest.raises(grpvss.InputError) as raised:
        cell.verify_program(file)
    assert raised.value.file == file
    assert raised.value.line == 5
    assert completed.stderr == f"grpvss: error: {raised.value}\n"


def test_a_thesis_robot_is_refused_for_a_program():
    data = SOURCE_DIR / "data" / "ibm7545"
    with pytest.raises(grpvss.InputError) as raised:
        grpvss.load_program(PROGRAMS / "ur5e-clear.script", str(data / "robot.txt"))
    assert "a URDF robot in a cell" in str(raised.value)


def test_two_threads_verify_programs_at_once(cell):
    session = cell.session()
    programs = [grpvss.load_program(PROGRAMS / name, cell.robot)
                for name in ("ur5e-clear.script", "ur5e-through-post.script")]
    results = run_in_two_threads_at_once(lambda i: session.verify_program(programs[i]))
    assert [r.verdict.name for r in results] == ["CLEAR", "COLLISION"]

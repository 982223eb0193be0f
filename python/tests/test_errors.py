"""Bad input raises grpvss.InputError (a ValueError) carrying file, line, expected and found,
with the message the CLI prints for the same file."""
import pytest

import grpvss
from conftest import ENVIRONMENT, PATH, ROBOT, run_cli


def broken_robot(tmp_path):
    lines = open(ROBOT).read().splitlines()
    lines[2] = "0.0,abc,15.8,0.0,0.0,200.0,2.,1.8"  # line 3: joint 1
    file = tmp_path / "robot.txt"
    file.write_text("\n".join(lines) + "\n")
    return str(file)


def test_input_error_names_file_line_expected_found(tmp_path):
    file = broken_robot(tmp_path)
    with pytest.raises(grpvss.InputError) as raised:
        grpvss.load_robot(file)
    error = raised.value
    assert isinstance(error, ValueError)
    assert (error.file, error.line) == (file, 3)
    assert error.expected == "a number for joint 1 (alpha, d, a, home, MIN, MAX, acc, dec)"
    assert error.found == "'abc'"
    assert str(error) == f"{file}:3: expected {error.expected}, found 'abc'"
    completed = run_cli("verify", "--robot", file, "--env", ENVIRONMENT, "--path", PATH,
                        "--tolerance", "0.5", "--quiet")
    assert completed.returncode == 2
    assert str(error) in completed.stderr


def test_missing_file_and_bad_options():
    with pytest.raises(grpvss.InputError) as raised:
        grpvss.load_environment("/nonexistent/environment.txt")
    assert raised.value.file == "/nonexistent/environment.txt" and raised.value.line == 0
    with pytest.raises(grpvss.InputError) as raised:
        grpvss.verify(ROBOT, ENVIRONMENT, PATH, tolerance=-1.0)
    assert raised.value.file == "tolerance"
    assert raised.value.expected == "a finite number > 0"
    with pytest.raises(grpvss.InputError) as raised:
        grpvss.verify(ROBOT, ENVIRONMENT, PATH, tolerance=0.5, mode="fast")
    assert (raised.value.file, raised.value.found) == ("mode", "'fast'")
    with pytest.raises(grpvss.InputError) as raised:
        grpvss.verify(ROBOT, ENVIRONMENT, PATH, tolerance=0.5, timing="sometimes")
    assert raised.value.file == "timing"


def test_a_path_of_another_robot_is_refused():
    puma = grpvss.load_robot(str(__import__("conftest").SOURCE_DIR / "data" / "puma560" / "robot.txt"))
    path = grpvss.load_path(PATH, grpvss.load_robot(ROBOT))
    session = grpvss.VerificationSession(puma, ENVIRONMENT, 0.5)
    with pytest.raises(ValueError, match="loaded for another robot"):
        session.verify(path)

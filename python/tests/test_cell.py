"""grpvss.load_cell against `grpvss verify --cell` on data/sixaxis (a URDF robot with STL
meshes, named obstacles, an allowed contact): the same defaults (the cell's tolerance,
synchronized timing), verdicts, JSON report and certificate byte for byte, names on the robot
and the obstacles, and check_certificate accepting the certificate."""
import json

import pytest

import grpvss
from conftest import SOURCE_DIR, run_cli

SIXAXIS = SOURCE_DIR / "data" / "sixaxis"
CELL = str(SIXAXIS / "cell.yaml")


def cli_verify_cell(tmp_path, path):
    report = tmp_path / "report.json"
    certificate = tmp_path / "certificate.json"
    completed = run_cli("verify", "--cell", CELL, "--path", path, "--json", str(report),
                        "--certificate", str(certificate), "--quiet", "--force", "--no-cache")
    assert completed.returncode in (0, 1), completed.stderr
    return completed.returncode, report.read_text(), certificate.read_text()


def test_a_cell_loads_with_names_units_and_defaults():
    cell = grpvss.load_cell(CELL)
    assert cell.tolerance == 0.005          # metres, from `tolerance` in the cell
    assert cell.robot.from_cell
    assert cell.robot.joint_names == [f"joint_{i}" for i in range(1, 7)]
    assert cell.robot.link_names[1] == "link_1" and cell.robot.link_names[4] == "link_4"
    assert cell.robot.link_count == 7
    assert "post" in cell.environment.obstacle_names
    assert "pedestal" in cell.environment.obstacle_names
    assert len(cell.environment.obstacle_names) == cell.environment.obstacle_count
    with pytest.raises(ValueError, match="general frames"):
        cell.robot.dh


@pytest.mark.parametrize("name,verdict,steps", [("path-clear.txt", "CLEAR", 4),
                                                ("path-collision.txt", "COLLISION", 8)])
def test_cell_verify_is_the_clis(tmp_path, name, verdict, steps):
    path = str(SIXAXIS / name)
    code, report_text, certificate_text = cli_verify_cell(tmp_path, path)
    cell = grpvss.load_cell(CELL)
    result = cell.verify(path)
    assert result.verdict.name == verdict == json.loads(report_text)["verdict"]
    assert result.exit_code == code
    assert result.step_count == steps
    generated_at = json.loads(report_text)["generated_at"]
    assert result.json_report(generated_at=generated_at) == report_text
    assert result.certificate.to_json() == certificate_text
    check = cell.check_certificate(path, result.certificate)
    assert check.accepted, check.messages


def test_episodes_name_their_link_and_obstacle():
    cell = grpvss.load_cell(CELL)
    result = cell.verify(str(SIXAXIS / "path-collision.txt"))
    named = sorted({(cell.robot.link_names[e.link], cell.environment.obstacle_names[e.obstacle])
                    for e in result.episodes})
    assert named == [("link_4", "post"), ("link_5", "post")]


def test_a_bad_cell_raises_input_error_naming_the_file_and_line(tmp_path):
    bad = tmp_path / "bad.yaml"
    bad.write_text("units: furlong\nrobot:\n  urdf: none.urdf\n")
    with pytest.raises(grpvss.InputError) as raised:
        grpvss.load_cell(bad)
    assert raised.value.file == str(bad)
    assert raised.value.line == 1

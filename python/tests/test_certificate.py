"""check_certificate against `grpvss check-certificate --json` on the same certificate files:
accepted, claim, the exact-check count, every failure message and the proven clearances."""
import json

import pytest

import grpvss
from conftest import DATA, ENVIRONMENT, PATH, ROBOT, cli_verify, run_cli


def cli_check(certificate, *options):
    completed = run_cli("check-certificate", "--robot", ROBOT, "--env", ENVIRONMENT, "--path",
                        PATH, "--json", *options, str(certificate))
    assert completed.returncode in (0, 1), completed.stderr
    return completed.returncode, json.loads(completed.stdout)


def assert_same_as_cli(report, code, expected):
    assert report.accepted == expected["accepted"]
    assert report.exit_code == code
    assert report.claim.name == expected["claim"]
    assert report.inequalities_checked == expected["inequalities_checked"]
    assert report.failures == report.messages == expected["failures"]
    assert report.timing == expected["motion_model"]["timing"]
    assert report.ik == expected["motion_model"]["ik"]
    assert [(c.link, c.lower_bound, c.step) for c in report.motion_clearances] == \
        [(c["link"], c["lower_bound"], c["step"]) for c in expected["motion_clearances"]]


def test_accepts_the_cli_certificate_and_its_own(tmp_path):
    cli_verify(tmp_path, ROBOT, ENVIRONMENT, PATH, 0.5)
    file = tmp_path / "certificate.json"
    code, expected = cli_check(file)
    assert code == 0 and expected["accepted"]
    assert_same_as_cli(grpvss.check_certificate(ROBOT, ENVIRONMENT, PATH, str(file)), code, expected)
    result = grpvss.verify(ROBOT, ENVIRONMENT, PATH, 0.5)
    assert_same_as_cli(grpvss.check_certificate(ROBOT, ENVIRONMENT, PATH, result.certificate),
                       code, expected)


def test_rejects_a_tampered_lower_bound_with_the_cli_messages(tmp_path):
    cli_verify(tmp_path, ROBOT, ENVIRONMENT, PATH, 0.5)
    document = json.loads((tmp_path / "certificate.json").read_text())
    evidence = document["segments"][0]["steps"][0]["hulls"][0]["evidence"][0]
    evidence["lower_bound"] *= 10.0
    tampered = tmp_path / "tampered.json"
    tampered.write_text(json.dumps(document))
    code, expected = cli_check(tampered)
    assert code == 1 and not expected["accepted"] and expected["failures"]
    report = grpvss.check_certificate(ROBOT, ENVIRONMENT, PATH, tampered)
    assert not report.accepted
    assert_same_as_cli(report, code, expected)


def test_rejects_a_certificate_of_other_inputs():
    result = grpvss.verify(ROBOT, ENVIRONMENT, PATH, 0.5)
    other_path = str(DATA / "path-output-sample.txt")
    report = grpvss.check_certificate(ROBOT, ENVIRONMENT, other_path, result.certificate)
    assert not report.accepted
    assert any("path" in message for message in report.messages)


def test_refuses_another_timing_than_the_certificates(tmp_path):
    result = grpvss.verify(ROBOT, ENVIRONMENT, PATH, 0.5)
    with pytest.raises(grpvss.InputError) as raised:
        grpvss.check_certificate(ROBOT, ENVIRONMENT, PATH, result.certificate, timing="synchronized")
    assert raised.value.file == "timing"
    assert raised.value.found == "synchronized"

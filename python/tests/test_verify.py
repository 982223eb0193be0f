"""grpvss.verify against `grpvss verify --json --certificate` on the same inputs: the same
verdict and exit code, the JSON report byte for byte, the certificate byte for byte, and the
numpy arrays equal to the report's numbers."""
import json
import math
import pathlib

import numpy as np
import pytest

import grpvss
from conftest import DATA, ROBOT, cli_verify

HERE = pathlib.Path(__file__).parent
PTP = str(HERE / "data" / "ptp-operation.txt")


def env(name):
    return str(DATA / f"{name}.txt")


# (environment, path, tolerance, extra CLI options, expected verdict)
CASES = [
    (env("environment"), str(DATA / "path.txt"), 0.5, [], "COLLISION"),
    (env("environment"), str(DATA / "path-output-sample.txt"), 2.0, [], "COLLISION"),
    (env("bench-environment-near-miss"), PTP, 0.5, [], "CLEAR"),
    (env("bench-environment-near-miss"), PTP, 0.7, [], "WITHIN_TOLERANCE"),
    (env("bench-environment-within-tolerance"), PTP, 2.0, ["--timing", "synchronized"],
     "WITHIN_TOLERANCE"),
    (env("bench-environment-cp-line"), str(DATA / "path.txt"), 0.5, ["--cp-speed", "2"], "ERROR"),
    (env("bench-environment"), PTP, 0.5, ["--mode", "thesis"], "CLEAR"),
    # The thesis's step rule steps over the sample's collision (README, docs/verification.md).
    (env("environment"), str(DATA / "path.txt"), 0.5, ["--mode", "thesis", "--offset", "cube"],
     "CLEAR"),
]


def keyword_options(options):
    names = {"--timing": "timing", "--cp-speed": "cp_speed", "--mode": "mode", "--offset": "offset"}
    keywords = {names[options[i]]: options[i + 1] for i in range(0, len(options), 2)}
    if "cp_speed" in keywords:
        keywords["cp_speed"] = float(keywords["cp_speed"])
    return keywords


def in_file_units(robot, q):
    return [math.degrees(v) if kind == "revolute" else v
            for v, kind in zip(q, robot.joint_types)]


@pytest.mark.parametrize("environment,path,tolerance,options,verdict", CASES)
def test_same_verdict_report_and_certificate_as_the_cli(tmp_path, environment, path, tolerance,
                                                        options, verdict):
    code, report_text, certificate_text = cli_verify(tmp_path, ROBOT, environment, path,
                                                     tolerance, *options)
    result = grpvss.verify(ROBOT, environment, path, tolerance, **keyword_options(options))
    assert result.verdict == getattr(grpvss.Verdict, verdict)
    assert result.verdict.name == json.loads(report_text)["verdict"] == verdict
    assert result.exit_code == code == grpvss.exit_code_of(result.verdict)
    generated_at = json.loads(report_text)["generated_at"]
    assert result.json_report(generated_at=generated_at) == report_text
    if certificate_text is None:
        assert result.certificate is None
    else:
        assert result.certificate.to_json() == certificate_text
        assert result.certificate.claim == result.verdict


@pytest.mark.parametrize("environment,path,tolerance,options,verdict", CASES[:6])
def test_arrays_hold_the_report_numbers(tmp_path, environment, path, tolerance, options, verdict):
    _, report_text, _ = cli_verify(tmp_path, ROBOT, environment, path, tolerance, *options)
    report = json.loads(report_text)
    robot = grpvss.load_robot(ROBOT)
    result = grpvss.verify(robot, environment, path, tolerance, **keyword_options(options))
    steps = report["steps"]
    assert result.step_count == len(steps) == report["total_steps"]
    np.testing.assert_array_equal(result.step_indices, [s["index"] for s in steps])
    np.testing.assert_array_equal(result.step_segments, [s["segment"] for s in steps])
    np.testing.assert_array_equal(result.times, [s["path_time"] for s in steps])
    assert result.configurations.shape == (len(steps), 4)
    for q, step in zip(result.configurations, steps):
        np.testing.assert_allclose(in_file_units(robot, q), step["joint_values"], rtol=1e-15,
                                   atol=0)
    np.testing.assert_array_equal(result.end_effector_positions, [s["end_effector"] for s in steps])
    clearances = [[math.inf if l["clearance"] is None else l["clearance"] for l in s["links"]]
                  for s in steps]
    np.testing.assert_array_equal(result.clearances, np.array(clearances).reshape(-1, 5))
    motion = [[math.nan if l["motion_clearance"] is None else l["motion_clearance"]
               for l in s["links"]] for s in steps]
    np.testing.assert_array_equal(result.motion_clearances, np.array(motion).reshape(-1, 5))
    np.testing.assert_array_equal(result.unexpanded_collides,
                                  [s["unexpanded_collides"] for s in steps])
    np.testing.assert_array_equal(result.expanded_interferes,
                                  [s["expanded_interferes"] for s in steps])
    assert result.collision_step == report["collision_step"]
    assert result.total_cycle_time == report["total_cycle_time"]
    assert [(c.link, c.min_clearance, c.step, c.obstacle) for c in result.link_clearances] == \
        [(c["link"], c["min_clearance"], c["step"], c["obstacle"]) for c in report["link_clearances"]]
    assert [(e.link, e.hull, e.obstacle, e.first_step, e.last_step, e.first_collision_step,
             e.cleared_step, e.cleared_time) for e in result.episodes] == \
        [(e["link"], e["hull"], e["obstacle"], e["first_step"], e["last_step"],
          e["first_collision_step"], e["cleared_step"], e["cleared_time"])
         for e in report["interference_episodes"]]
    assert [(e.code, e.segment, e.step, e.message) for e in result.errors] == \
        [(e["code"], e["segment"], e["step"], e["message"]) for e in report["errors"]]
    for step in steps:
        points = result.interference_points(step["index"])
        assert [(p.link, p.hull, p.obstacle, list(p.p_W), p.kind) for p in points] == \
            [(p["link"], p["hull"], p["obstacle"], p["point"], p["kind"])
             for p in step["interference_points"]]


def test_the_sample_collides_with_episodes_naming_link_and_obstacle():
    result = grpvss.verify(ROBOT, str(DATA / "environment.txt"), str(DATA / "path.txt"), 0.5)
    assert result.verdict == grpvss.Verdict.COLLISION
    assert result.exit_code == 1
    assert result.step_count == 23
    assert result.episodes, "the sample's collision is an episode"
    colliding = [e for e in result.episodes if e.first_collision_step is not None]
    assert colliding and all(0 <= e.link <= 4 and e.obstacle in (0, 1) for e in colliding)


def test_a_session_verifies_many_paths_against_one_cell():
    session = grpvss.VerificationSession(ROBOT, env("bench-environment-near-miss"), 0.5)
    assert (session.tolerance, session.mode, session.offset) == (0.5, "certified",
                                                                 "rhombicuboctahedron")
    first = session.verify(PTP)
    second = session.verify(grpvss.load_path(PTP, session.robot))
    one_shot = grpvss.verify(ROBOT, env("bench-environment-near-miss"), PTP, 0.5)
    assert first.verdict == second.verdict == one_shot.verdict == grpvss.Verdict.CLEAR
    assert first.json_report("t") == second.json_report("t") == one_shot.json_report("t")
    assert grpvss.NOT_QUALIFIED == grpvss.Verdict.NOT_QUALIFIED == grpvss.Verdict.ERROR
    assert grpvss.Verdict.NOT_QUALIFIED.name == "ERROR"


def test_certificate_save_writes_the_cli_bytes_and_refuses_to_overwrite(tmp_path):
    _, _, certificate_text = cli_verify(tmp_path, ROBOT, env("environment"), str(DATA / "path.txt"), 0.5)
    result = grpvss.verify(ROBOT, env("environment"), str(DATA / "path.txt"), 0.5)
    target = tmp_path / "saved.json"
    result.certificate.save(str(target))
    assert target.read_text() == certificate_text
    with pytest.raises(grpvss.InputError):
        result.certificate.save(str(target))
    result.certificate.save(str(target), force=True)


def test_claim_steps_is_the_claim_before_issue_20_7_and_motion_the_default():
    # docs/verification.md#claim: the sample collides either way; claim steps keeps the earlier
    # rule (23 steps), the default claim motion aims its steps at g >= tolerance (23 as well since
    # the step's axis distances, proofs/motion-bound.md#lemma-axis-distance-along-step).
    steps = grpvss.verify(ROBOT, str(DATA / "environment.txt"), str(DATA / "path.txt"), 0.5,
                          claim="steps")
    motion = grpvss.verify(ROBOT, str(DATA / "environment.txt"), str(DATA / "path.txt"), 0.5)
    assert (steps.verdict, steps.step_count) == (grpvss.Verdict.COLLISION, 23)
    assert (motion.verdict, motion.step_count) == (grpvss.Verdict.COLLISION, 23)
    assert json.loads(steps.json_report())["claim"] == "steps"
    assert json.loads(motion.json_report())["claim"] == "motion"
    with pytest.raises(grpvss.InputError, match="motion or steps"):
        grpvss.verify(ROBOT, str(DATA / "environment.txt"), str(DATA / "path.txt"), 0.5,
                      claim="everywhere")

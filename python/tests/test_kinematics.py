"""Forward kinematics against the CLI's report (the scene's X_WL of every step, the end
effector) and against a DH product written here."""
import json

import numpy as np
import pytest

import grpvss
from conftest import ENVIRONMENT, PATH, ROBOT, cli_verify


def dh_transform(theta, d, a, alpha):
    """Standard DH: Rot_z(theta) Trans_z(d) Trans_x(a) Rot_x(alpha)."""
    ct, st, ca, sa = np.cos(theta), np.sin(theta), np.cos(alpha), np.sin(alpha)
    return np.array([[ct, -st * ca, st * sa, a * ct],
                     [st, ct * ca, -ct * sa, a * st],
                     [0.0, sa, ca, d],
                     [0.0, 0.0, 0.0, 1.0]])


def reference_poses(robot, q):
    poses = [np.eye(4)]
    for (theta, d, a, alpha), kind, value in zip(robot.dh, robot.joint_types, q):
        if kind == "revolute":
            theta = theta + value
        else:
            d = d + value
        poses.append(poses[-1] @ dh_transform(theta, d, a, alpha))
    return poses


def test_link_frames_match_the_cli_scene_bit_for_bit(tmp_path):
    robot = grpvss.load_robot(ROBOT)
    result = grpvss.verify(robot, ENVIRONMENT, PATH, tolerance=0.5)
    _, report_text, _ = cli_verify(tmp_path, ROBOT, ENVIRONMENT, PATH, 0.5)
    scene_steps = json.loads(report_text)["scene"]["steps"]
    assert len(scene_steps) == result.step_count == 23
    for q, scene_step in zip(result.configurations, scene_steps):
        poses = robot.forward_kinematics(q)
        assert len(poses) == robot.link_count
        for pose, X_WL in zip(poses, scene_step["X_WL"]):
            assert pose.shape == (4, 4)
            np.testing.assert_array_equal(pose.reshape(16), X_WL)  # row-major, exact


def test_link_frames_match_a_dh_product():
    robot = grpvss.load_robot(ROBOT)
    rng = np.random.default_rng(7)
    for _ in range(50):
        q = rng.uniform(robot.limits[:, 0], robot.limits[:, 1])
        for pose, reference in zip(robot.forward_kinematics(q), reference_poses(robot, q)):
            np.testing.assert_allclose(pose, reference, rtol=0, atol=1e-12)


def test_tcp_pose_is_the_last_frame_and_the_reported_end_effector():
    robot = grpvss.load_robot(ROBOT)
    result = grpvss.verify(robot, ENVIRONMENT, PATH, tolerance=0.5)
    for q, p_W in zip(result.configurations, result.end_effector_positions):
        tcp = robot.tcp_pose(q)
        np.testing.assert_array_equal(tcp, robot.forward_kinematics(q)[-1])
        np.testing.assert_allclose(tcp[:3, 3], p_W, rtol=0, atol=1e-12)


def test_wrong_joint_count_raises_value_error():
    robot = grpvss.load_robot(ROBOT)
    with pytest.raises(ValueError, match="expected 4 joint values, found 3"):
        robot.forward_kinematics([0.0, 0.0, 0.0])

"""load_robot, load_environment, load_path: what the thesis sample files hold."""
import math

import numpy as np

import grpvss
from conftest import DATA, ENVIRONMENT, PATH, ROBOT


def test_robot_holds_the_sample_robot_file():
    robot = grpvss.load_robot(ROBOT)
    assert robot.joint_count == 4
    assert robot.link_count == 5
    assert robot.joint_indices == [1, 2, 3, 4]
    assert robot.joint_types == ["revolute", "revolute", "prismatic", "revolute"]
    # joint lines: alpha, d, a, home, MIN, MAX, acc, dec (degrees for revolute joints)
    np.testing.assert_array_equal(robot.home, [0.0, 0.0, 0.0, 0.0])
    np.testing.assert_array_equal(robot.limits[0], [0.0, math.radians(200.0)])
    np.testing.assert_array_equal(robot.limits[1], [0.0, math.radians(135.0)])
    np.testing.assert_array_equal(robot.limits[2], [0.0, 9.8])
    np.testing.assert_array_equal(robot.limits[3], [math.radians(-180.0), math.radians(180.0)])
    np.testing.assert_array_equal(robot.dh[0], [0.0, 25.5, 15.8, 0.0])
    np.testing.assert_array_equal(robot.dh[1], [0.0, 0.0, 9.8, math.radians(180.0)])
    np.testing.assert_array_equal(robot.dh[3], [0.0, 15.05, 0.0, 0.0])
    assert len(robot.sha256) == 64


def test_environment_and_path():
    environment = grpvss.load_environment(ENVIRONMENT)
    assert environment.obstacle_count == 2
    assert environment.smallest_angle == math.radians(90.0)
    assert environment.smallest_thickness == 5.0
    robot = grpvss.load_robot(ROBOT)
    path = grpvss.load_path(PATH, robot)
    assert path.segment_kinds == ["ptp_joint", "ptp_world", "cp_line"]
    assert path.robot is robot
    sample = grpvss.load_path(DATA / "path-output-sample.txt", robot)
    assert sample.segment_kinds == ["ptp_world", "cp_line", "ptp_joint", "cp_line"]

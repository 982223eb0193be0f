"""GRPVSS from Python: load cells and the thesis files, forward kinematics, verify paths,
planners' joint trajectories (numpy arrays or CSV / ROS JSON files) and robot programs
(URScript, KUKA KRL, ABB RAPID), certificates.

The native module ``_grpvss`` (pybind11, python/src/) calls the C++ library exactly as the
``grpvss`` command does; this package adds keyword arguments, file-name conveniences and the
``InputError`` exception. Units are the library's: lengths in the files' unit, revolute joint
values in radians. Batches on Dask: :mod:`grpvss.dask`. Documentation: docs/python.md.
"""
import os
import tempfile

import _grpvss as _native
from _grpvss import (Certificate, CheckedMotionClearance, CheckReport, ConfigurationFinding,
                     ConfigurationVerdict, Environment, Episode,
                     InterferencePoint, JointTrajectory, LinkClearance, Path, PathError, Result,
                     Robot, RobotProgram, Segment, Verdict, exit_code_of)

__all__ = [
    "InputError", "Verdict", "Robot", "Environment", "Path", "Result", "Certificate",
    "CheckReport", "Episode", "PathError", "LinkClearance", "Segment", "InterferencePoint",
    "CheckedMotionClearance", "VerificationSession", "Cell", "load_cell", "load_robot",
    "load_environment", "load_path", "verify", "check_certificate", "exit_code_of",
    "JointTrajectory", "joint_trajectory", "load_trajectory", "RobotProgram", "load_program",
    "ConfigurationVerdict", "ConfigurationFinding",
]

#: The label of a trajectory given as arrays: the name reports give it (``motion_model``,
#: ``inputs.path.file``) and errors name. Save the arrays under this name
#: (:meth:`JointTrajectory.save`) and ``grpvss verify --trajectory`` reports them identically.
ARRAYS_LABEL = "trajectory.csv"

#: The verdict for a path that is not qualified (thesis errors 1-6, errors 7-9): exit code 4.
#: ``Verdict.NOT_QUALIFIED`` is the same value; its ``name`` is ``"ERROR"``, as in the reports.
NOT_QUALIFIED = Verdict.NOT_QUALIFIED


class InputError(ValueError):
    """Bad input, located in a file: ``file``, ``line`` (0: the file as a whole, or an option
    such as ``tolerance``), ``expected`` and ``found`` (empty when nothing was found)."""

    def __init__(self, message, file="", line=0, expected="", found=""):
        super().__init__(message)
        self.file = file
        self.line = line
        self.expected = expected
        self.found = found


def load_robot(file):
    """Reads a thesis robot file (Appendix A.1.1.1) into a :class:`Robot`."""
    return _native.load_robot(os.fspath(file))


def load_environment(file):
    """Reads a thesis environment file (Appendix A.1.1.2) into an :class:`Environment`."""
    return _native.load_environment(os.fspath(file))


class Cell:
    """A cell file (docs/cell-format.md) as ``grpvss verify --cell`` loads it: a URDF or
    thesis robot on its base with its TCP, named obstacles, and the defaults the cell gives.
    Lengths are the model's (metres for a URDF robot, whatever the cell's ``units``);
    ``tolerance`` and ``cp_speed`` are None when the cell gives none. ``warnings``: the
    inputs' warnings as (file, line, text), which ``grpvss verify`` prints."""

    def __init__(self, file, robot, environment, tolerance, cp_speed, warnings):
        self.file = file
        self.robot = robot
        self.environment = environment
        self.tolerance = tolerance
        self.cp_speed = cp_speed
        self.warnings = list(warnings)

    def session(self, tolerance=None, mode="certified", offset="auto"):
        """The prepared set-up at ``tolerance`` (default: the cell's) for many paths."""
        if tolerance is None:
            tolerance = self.tolerance
        if tolerance is None:
            raise InputError(f"{self.file}:0: expected a tolerance (the cell gives none)",
                             self.file, 0, "a tolerance (the cell gives none)")
        return VerificationSession(self.robot, self.environment, tolerance, mode=mode,
                                   offset=offset, cp_speed=self.cp_speed)

    def verify(self, path, tolerance=None, mode="certified", offset="auto", timing=None,
               cp_speed=None, ik="auto", profile_table=None, claim="motion"):
        """One verification of ``path`` (a :class:`Path` or a thesis path file, lengths in
        the cell's unit) with the cell's defaults: its tolerance and CP speed, synchronized
        timing."""
        return self.session(tolerance, mode=mode, offset=offset).verify(
            path, timing=timing, cp_speed=cp_speed, ik=ik, profile_table=profile_table,
            claim=claim)

    def check_certificate(self, path, certificate, timing=None, ik=None, profile_table=None):
        """:func:`check_certificate` against this cell's robot and obstacles (``path``: a
        path, or a :class:`JointTrajectory`)."""
        return check_certificate(self.robot, self.environment, path, certificate,
                                 timing=timing, ik=ik, profile_table=profile_table)

    def verify_trajectory(self, times, positions, velocities=None, joint_names=None,
                          tolerance=None, mode="certified", offset="auto", ik="auto",
                          label=ARRAYS_LABEL, claim="motion"):
        """Verifies a joint trajectory given as arrays (:func:`joint_trajectory`) as
        ``grpvss verify --cell --trajectory`` verifies its CSV form; returns a :class:`Result`
        (``result.trajectory`` re-checks the certificate)."""
        trajectory = joint_trajectory(self.robot, times, positions, velocities=velocities,
                                      joint_names=joint_names, label=label)
        return self.session(tolerance, mode=mode, offset=offset).verify_joint_trajectory(
            trajectory, ik=ik, claim=claim)

    def verify_trajectory_file(self, file, tolerance=None, mode="certified", offset="auto",
                               ik="auto", claim="motion"):
        """Verifies a trajectory file (CSV or ROS JSON) as ``grpvss verify --cell --trajectory
        FILE`` does."""
        return self.session(tolerance, mode=mode, offset=offset).verify_joint_trajectory(
            load_trajectory(file, self.robot), ik=ik, claim=claim)

    def check_trajectory_certificate(self, trajectory, certificate, ik=None):
        """Re-verifies a trajectory's certificate, as ``grpvss check-certificate --cell
        --trajectory`` does. ``trajectory``: a :class:`JointTrajectory` (``result.trajectory``,
        or :func:`joint_trajectory` of the same arrays) or a trajectory file."""
        return check_certificate(self.robot, self.environment, _as_trajectory(trajectory,
                                                                              self.robot),
                                 certificate, ik=ik)

    def verify_program(self, file, tolerance=None, mode="certified", offset="auto", ik="auto",
                       start=None, claim="motion"):
        """Verifies a robot program (URScript ``.script``, KUKA KRL ``.src``, ABB RAPID
        ``.mod``) as ``grpvss verify --cell --program FILE`` does: each joint motion a
        synchronized PTP segment, Cartesian targets by IK (``ik``) in the configuration the
        program names, from ``start`` (joint values in rad) or the robot's home. Returns a
        :class:`Result`; ``result.warnings`` holds the reader's warnings as (file, line, text)
        and ``result.program`` the :class:`RobotProgram`. A refused motion (linear, circular,
        blended) or an unreachable target raises :class:`InputError` naming its file and line."""
        program = load_program(file, self.robot, ik=ik, start=start)
        return self.session(tolerance, mode=mode, offset=offset).verify_program(program,
                                                                                claim=claim)

    def check_program_certificate(self, program, certificate, ik="auto", start=None):
        """Re-verifies a program's certificate, as ``grpvss check-certificate --cell --program``
        does. ``program``: a :class:`RobotProgram` (``result.program``) or a program file (read
        with ``ik`` and ``start``)."""
        return check_certificate(self.robot, self.environment,
                                 _as_program(program, self.robot, ik, start), certificate)

    def __repr__(self):
        return (f"<grpvss.Cell {self.file}: {self.robot.joint_count} joints, "
                f"{self.environment.obstacle_count} obstacle hulls>")


def load_cell(file, package_paths=()):
    """Reads a cell file (YAML, docs/cell-format.md) and everything it names (URDF, SRDF,
    meshes, thesis files) into a :class:`Cell`. ``package_paths``: directories searched for
    ``package://NAME/...`` before the cell's own ``package_paths`` and ROS_PACKAGE_PATH."""
    file = os.fspath(file)
    robot, environment, tolerance, cp_speed, warnings = _native._load_cell(
        file, [os.fspath(p) for p in package_paths])
    return Cell(file, robot, environment, tolerance, cp_speed, warnings)


def load_path(file, robot):
    """Reads a thesis path file (Appendix A.1.3) for ``robot`` (a :class:`Robot` or a file)."""
    return _native.load_path(os.fspath(file), _as_robot(robot))


def joint_trajectory(robot, times, positions, velocities=None, joint_names=None,
                     label=ARRAYS_LABEL):
    """A joint trajectory for ``robot`` from arrays: ``times`` (N,) in s, ``positions`` (N, J)
    and optionally ``velocities`` (N, J) in rad (m) and rad/s (m/s); columns in
    ``joint_names`` order, by default ``robot.joint_names``. Interpolated as
    docs/trajectories.md section 10 says (linear, or cubic Hermite with velocities).
    The arrays are validated, digested and verified as their canonical CSV text
    (:meth:`JointTrajectory.to_csv`): a shape error raises :class:`InputError` naming the
    argument (``file`` ``"positions"``); any other (times not increasing, a joint the robot
    does not have, a position limit left along the interpolation) names ``label`` and the line
    of that text: line 1 the joint names, line k+2 waypoint k (``times[k]``)."""
    import numpy
    velocities = None if velocities is None else numpy.asarray(velocities, dtype=float)
    names = None if joint_names is None else [str(name) for name in joint_names]
    return _native._trajectory_from_arrays(numpy.asarray(times, dtype=float),
                                           numpy.asarray(positions, dtype=float), velocities,
                                           names, _as_robot(robot), label)


def load_trajectory(file, robot):
    """Reads a trajectory file (CSV or ROS ``JointTrajectory`` JSON, docs/trajectories.md
    section 9) for ``robot``, as ``grpvss verify --trajectory`` reads it."""
    return _native._load_trajectory(os.fspath(file), _as_robot(robot))


def load_program(file, robot, ik="auto", start=None):
    """Reads a robot program (docs/robot-programs.md#verifying-a-program) and resolves it
    against ``robot`` (a cell's: its base and tool place the targets) with the IK ``ik``, from
    ``start`` (rad) or the robot's home, as ``grpvss verify --program`` does. Returns a
    :class:`RobotProgram` (``warnings``, ``targets``, ``motion_model``, ``digest``)."""
    import numpy
    start = None if start is None else numpy.asarray(start, dtype=float)
    return _native._load_program(os.fspath(file), _as_robot(robot), ik, start)


def _as_program(program, robot, ik="auto", start=None):
    if not isinstance(program, RobotProgram):
        return load_program(program, robot, ik=ik, start=start)
    if program.robot is robot:
        return program
    raise ValueError(f"{program.file} was loaded for another robot ({program.robot.file})")


def _as_trajectory(trajectory, robot):
    if not isinstance(trajectory, JointTrajectory):
        return load_trajectory(trajectory, robot)
    if trajectory.robot is robot:
        return trajectory
    raise ValueError(f"{trajectory.file} was loaded for another robot ({trajectory.robot.file})")


def _as_robot(robot):
    return robot if isinstance(robot, Robot) else load_robot(robot)


def _as_environment(environment):
    return environment if isinstance(environment, Environment) else load_environment(environment)


def _as_path(path, robot):
    if not isinstance(path, Path):
        return load_path(path, robot)
    if path.robot is robot:
        return path
    if path.robot.sha256 != robot.sha256:
        raise ValueError(f"{path.file} was loaded for another robot ({path.robot.file})")
    return load_path(path.file, robot)  # the same robot file, loaded twice


class VerificationSession:
    """The prepared cell: the exact set-up (hulls, tolerance offsets) of one robot in one
    environment at one tolerance, mode and offset shape, built once. :meth:`verify` runs any
    number of paths against it, from any number of threads (the GIL is released while a path
    is verified)."""

    def __init__(self, robot, environment, tolerance, mode="certified", offset="auto",
                 cp_speed=None):
        self._native = _native.Session(_as_robot(robot), _as_environment(environment),
                                       float(tolerance), mode, offset)
        self._cp_speed = 1.0 if cp_speed is None else float(cp_speed)

    robot = property(lambda self: self._native.robot)
    environment = property(lambda self: self._native.environment)
    tolerance = property(lambda self: self._native.tolerance)
    mode = property(lambda self: self._native.mode)
    offset = property(lambda self: self._native.offset)

    def verify(self, path, timing=None, cp_speed=None, ik="auto", profile_table=None,
               claim="motion"):
        """Verifies ``path`` (a :class:`Path` or a path file) and returns a :class:`Result`.
        ``timing``, ``cp_speed``, ``ik``, ``profile_table`` and ``claim`` (``motion`` or
        ``steps``, docs/verification.md#claim) are ``grpvss verify``'s options;
        unset, timing is synchronized for a cell's robot and independent for a thesis robot
        file, and the CP speed is the session's (a cell's, else 1)."""
        if timing is None:
            timing = "synchronized" if self.robot.from_cell else "independent"
        if cp_speed is None:
            cp_speed = self._cp_speed
        table = os.fspath(profile_table) if profile_table is not None else ""
        return self._native._verify(_as_path(path, self.robot), timing, float(cp_speed), ik,
                                    table, claim)

    def verify_joint_trajectory(self, trajectory, ik="auto", claim="motion"):
        """Verifies a :class:`JointTrajectory` (or a trajectory file) and returns a
        :class:`Result`, as ``grpvss verify --trajectory`` does (certified mode only)."""
        timing = "synchronized" if self.robot.from_cell else "independent"
        return self._native._verify_trajectory(_as_trajectory(trajectory, self.robot), timing,
                                               self._cp_speed, ik, claim)

    def verify_program(self, program, ik="auto", start=None, claim="motion"):
        """Verifies a :class:`RobotProgram` (or a program file, read with ``ik`` and ``start``)
        as ``grpvss verify --program`` does: synchronized PTP, the session's CP speed, the
        ``claim`` of :meth:`verify`; the GIL is released while it runs."""
        return self._native._verify_program(_as_program(program, self.robot, ik, start),
                                            self._cp_speed, claim)

    def verify_trajectory(self, times, positions, velocities=None, joint_names=None, ik="auto",
                          label=ARRAYS_LABEL, claim="motion"):
        """Verifies a joint trajectory given as arrays (:func:`joint_trajectory`)."""
        return self.verify_joint_trajectory(
            joint_trajectory(self.robot, times, positions, velocities=velocities,
                             joint_names=joint_names, label=label), ik=ik, claim=claim)

    def verify_trajectory_file(self, file, ik="auto", claim="motion"):
        """Verifies a trajectory file (CSV or ROS JSON)."""
        return self.verify_joint_trajectory(load_trajectory(file, self.robot), ik=ik,
                                            claim=claim)

    def check_configurations(self, configurations):
        """The certified verdict of each configuration: ``configurations`` is an array of
        rows of joint values (rad / length, within the limits: a planner's samples), one
        :class:`ConfigurationVerdict` per row (``verdict``, ``clear``, ``findings``: each
        link hull meeting an obstacle or another link hull, named as the reports name them).
        CLEAR proves every link farther than the tolerance from every obstacle and no two
        self-pair links touching (proofs/configuration-check.md). Rows are checked in order,
        each term's last slab tried first: nearby rows in sequence are cheapest. Certified
        mode only; the GIL is released while the rows are checked."""
        import numpy
        rows = numpy.asarray(configurations, dtype=float)
        if rows.size == 0:
            return []
        if rows.ndim == 1:
            rows = rows.reshape(1, -1)
        return self._native._check_configurations(numpy.ascontiguousarray(rows))

    def check_configuration(self, q):
        """:meth:`check_configurations` of one configuration."""
        return self.check_configurations([q])[0]


def verify(robot, environment, path, tolerance, mode="certified", offset="auto",
           timing=None, cp_speed=None, ik="auto", profile_table=None, claim="motion"):
    """One verification, as ``grpvss verify`` runs it; arguments are objects or file names."""
    session = VerificationSession(robot, environment, tolerance, mode=mode, offset=offset)
    return session.verify(path, timing=timing, cp_speed=cp_speed, ik=ik,
                          profile_table=profile_table, claim=claim)


def check_certificate(robot, environment, path, certificate, timing=None, ik=None,
                      profile_table=None):
    """Re-verifies a certificate (a file, or a :class:`Certificate`) exactly from the inputs
    alone, as ``grpvss check-certificate`` does; returns a :class:`CheckReport`
    (``accepted``, ``messages``, ``exit_code``, ...). ``timing`` and ``ik``: what the caller
    expects (unset: the certificate's; another is refused with :class:`InputError`).
    ``path`` may be a :class:`JointTrajectory` (arrays or a file, as verified): its
    certificate is checked as ``grpvss check-certificate --trajectory`` checks it, and
    ``timing`` and ``profile_table`` are refused (the trajectory is the motion). ``path`` may
    be a :class:`RobotProgram` (``result.program``, or :func:`load_program`): checked as
    ``grpvss check-certificate --program`` checks it, with the program's IK (``ik``, if
    given, must name the same); ``timing`` other than synchronized and ``profile_table`` are
    refused."""
    robot = _as_robot(robot)
    environment = _as_environment(environment)
    if isinstance(path, RobotProgram):
        return _check_program(robot, environment, _as_program(path, robot), certificate,
                              timing, ik, profile_table)
    if isinstance(path, JointTrajectory):
        return _check_trajectory(robot, environment, _as_trajectory(path, robot), certificate,
                                 timing, ik, profile_table)
    path = _as_path(path, robot)
    table = os.fspath(profile_table) if profile_table is not None else ""
    if not isinstance(certificate, Certificate):
        return _native._check_certificate_file(robot, environment, path, os.fspath(certificate),
                                               timing, ik, table)
    with tempfile.TemporaryDirectory(prefix="grpvss-certificate-") as folder:
        file = os.path.join(folder, "certificate.json")
        certificate.save(file)
        return _native._check_certificate_file(robot, environment, path, file, timing, ik, table)


def _check_trajectory(robot, environment, trajectory, certificate, timing, ik, profile_table):
    for option, given in (("timing", timing), ("profile_table", profile_table)):
        if given is not None:
            raise InputError(f"{option}:0: expected no {option} with a trajectory (the "
                             "trajectory's waypoint times and interpolation are the motion), "
                             f"found {option}", option, 0,
                             f"no {option} with a trajectory", option)
    if not isinstance(certificate, Certificate):
        return _native._check_trajectory_certificate_file(robot, environment, trajectory,
                                                          os.fspath(certificate), ik)
    with tempfile.TemporaryDirectory(prefix="grpvss-certificate-") as folder:
        file = os.path.join(folder, "certificate.json")
        certificate.save(file)
        return _native._check_trajectory_certificate_file(robot, environment, trajectory, file,
                                                          ik)


def _check_program(robot, environment, program, certificate, timing, ik, profile_table):
    why = "a program is verified as the controller runs it: synchronized PTP, exact stops"
    if ik is not None and ik != program.ik:
        raise InputError(f"ik:0: expected the IK the program was resolved with "
                         f"('{program.ik}'), found '{ik}'", "ik", 0,
                         f"the IK the program was resolved with ('{program.ik}')", f"'{ik}'")
    for option, given in (("timing", timing not in (None, "synchronized")),
                          ("profile_table", profile_table is not None)):
        if given:
            raise InputError(f"{option}:0: expected no {option} with a program ({why}), found "
                             f"{option}", option, 0, f"no {option} with a program ({why})", option)
    if not isinstance(certificate, Certificate):
        return _native._check_program_certificate_file(robot, environment, program,
                                                       os.fspath(certificate))
    with tempfile.TemporaryDirectory(prefix="grpvss-certificate-") as folder:
        file = os.path.join(folder, "certificate.json")
        certificate.save(file)
        return _native._check_program_certificate_file(robot, environment, program, file)

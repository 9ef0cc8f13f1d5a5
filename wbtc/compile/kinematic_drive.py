"""Which robots without Physics Webots drives over the ground by kinematics, and with which wheels.

Webots moves a Robot that has no Physics when two of its joints make a differential drive
(`WbKinematicDifferentialWheels`): HingeJoints among the robot's own children, each with a
RotationalMotor and a Solid endPoint whose boundingObject holds a Cylinder, the two cylinders of the
same radius, the axes parallel, the anchors on the axle. The robot then slides by 2-D kinematics
from the motors' velocities (`wbtc.runtime.kinematic_drive`). A DifferentialWheels without Physics is
driven the same way from its own `wheelRadius`, `axleLength` and `slipNoise`
(`wbtc.scene.legacy_nodes` gave it its wheel joints).

Not honoured yet: Webots' check that both cylinders are as far from the robot's origin (the wheel
Solids' origins are compared instead).
"""

from __future__ import annotations

import numpy as np

from wbtc.compile.table import KinematicDrive
from wbtc.scene.legacy_nodes import WHEELS
from wbtc.scene.model import Node

#: Parallel enough (|a × b| for unit vectors) and equal enough (metres) for Webots' exact tests.
_TOLERANCE = 1e-6


def _biggest_cylinder(node: object) -> float:
    """The radius of the biggest Cylinder in a boundingObject (0 when there is none), as Webots looks."""
    if not isinstance(node, Node):
        return 0.0
    kind = node.base_type
    if kind == "Cylinder":
        return float(node.get("radius"))
    if kind == "Shape":
        return _biggest_cylinder(node.get("geometry"))
    if kind in ("Group", "Pose", "Transform"):
        return max((_biggest_cylinder(c) for c in node.get("children") or []), default=0.0)
    return 0.0


def _wheel(joint: Node) -> tuple[str, float, np.ndarray, np.ndarray, np.ndarray] | None:
    """(motor name, wheel radius, axis, anchor, wheel position) of a motorized wheel HingeJoint."""
    if joint.base_type != "HingeJoint":
        return None
    end = joint.get("endPoint")
    motors = [d for d in joint.get("device") or [] if isinstance(d, Node) and d.base_type == "RotationalMotor"]
    if not isinstance(end, Node) or not end.is_a("Solid") or not motors:
        return None
    radius = _biggest_cylinder(end.get("boundingObject"))
    if radius <= 0:
        return None
    params = joint.get("jointParameters")
    axis = np.asarray(params.get("axis") if isinstance(params, Node) else (1.0, 0.0, 0.0), dtype=float)
    anchor = np.asarray(params.get("anchor") if isinstance(params, Node) else (0.0, 0.0, 0.0), dtype=float)
    norm = float(np.linalg.norm(axis))
    if norm == 0:
        return None
    return str(motors[0].get("name")), radius, axis / norm, anchor, np.asarray(end.get("translation"), dtype=float)


def _pair(first: tuple, second: tuple) -> bool:
    _, radius1, axis1, anchor1, at1 = first
    _, radius2, axis2, anchor2, at2 = second
    if abs(radius1 - radius2) > _TOLERANCE or np.linalg.norm(np.cross(axis1, axis2)) > _TOLERANCE:
        return False
    between = anchor2 - anchor1  # on the axle (or the same point: the E-puck gives both wheels one anchor)
    if np.linalg.norm(np.cross(axis1, between)) > _TOLERANCE:
        return False
    return abs(float(np.linalg.norm(at1)) - float(np.linalg.norm(at2))) <= 1e-5


def find_drive(robot: Node) -> KinematicDrive | None:
    """The kinematic differential drive of a Robot without Physics (None when Webots would not drive it)."""
    if isinstance(robot.get("physics"), Node):
        return None
    if robot.base_type == "DifferentialWheels":
        names = [d.get("name") for c in robot.get("children") or [] if isinstance(c, Node)
                 and c.base_type == "HingeJoint" for d in c.get("device") or [] if isinstance(d, Node)]
        left, right = WHEELS["left wheel"][0], WHEELS["right wheel"][0]
        if left not in names or right not in names:
            return None
        return KinematicDrive((left, right), float(robot.get("wheelRadius")), float(robot.get("axleLength")),
                              float(robot.get("slipNoise")))
    wheels = [w for w in (_wheel(c) for c in robot.get("children") or [] if isinstance(c, Node)) if w is not None]
    for i, first in enumerate(wheels):
        for second in wheels[i + 1:]:
            if _pair(first, second):
                return KinematicDrive((first[0], second[0]), first[1])
    return None

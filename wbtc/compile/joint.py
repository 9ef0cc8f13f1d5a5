"""HingeJoint, Hinge2Joint, BallJoint and SliderJoint to MuJoCo joints on the endPoint's body.

Webots writes a joint's `axis` and `anchor` in the frame of the Solid that holds the joint, and the
endPoint's pose as it is at the joint's current `position`. MuJoCo writes joints in the child
body's frame, and its `ref` is exactly "the joint value at the pose written in the model", so the
endPoint's pose is kept and `ref = position`: MuJoCo then reports the same joint value Webots'
PositionSensor does, relative to the zero found by undoing `position` about the axis.

Stops (`minStop`, `maxStop`, with `stopERP` and `stopCFM`) become MuJoCo limits with ODE's stop rows
(`wbtc.compile.joint_stops`).

Not honoured yet: `suspensionSpringConstant`, `suspensionDampingConstant`, `suspensionAxis`; a
BallJoint's spring and damping per axis (a ball joint with devices is three hinges, each with its own
parameters; without devices it is one MuJoCo ball joint with the first parameters'); SolidReference
endPoints (closed loops). Brake devices are listed; the runtime applies their damping.

A joint with no Solid above it (at the top of the world, or in a top-level Pose or Group) is left
unattached, as Webots leaves it (its endPoint is a Solid of its own), with a warning.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

import mujoco
import numpy as np

from wbtc.compile import device, joint_stops
from wbtc.compile.context import COLLISION_GROUP, KINEMATIC_MASS, CompileContext, info
from wbtc.compile.frames import Frame, axis_angle_quat, quat_conj, quat_rotate, quat_to_mat
from wbtc.compile.table import RobotEntry
from wbtc.errors import UNATTACHED_JOINT
from wbtc.scene.model import Node
from wbtc.schema.registry import node_schema

if TYPE_CHECKING:
    from wbtc.compile.solid import BodyBuilder

_UNHONOURED = frozenset({"suspensionSpringConstant", "suspensionDampingConstant", "suspensionAxis"})


def param(params: Node | None, type_name: str, name: str) -> object:
    """A joint parameter: the node's value, or the default of `type_name` when the node is NULL."""
    if isinstance(params, Node):
        return params.get(name)
    field = node_schema(type_name).field(name)
    return field.default if field is not None else None


def slot_end(slot: Node, ctx: CompileContext) -> Node | None:
    """What a Slot holds: its endPoint, unless that is a Slot of a type that does not pair with it.

    Webots (WbNodeUtilities::isSlotTypeMatch) pairs two Slots when either type is empty, when their
    types are equal, or, for gendered types ("wheel+", "wheel-"), when they differ by the gender
    only; other pairs are refused and the inner Slot is left out.
    """
    end = slot.get("endPoint")
    if not isinstance(end, Node) or end.base_type != "Slot":
        return end if isinstance(end, Node) else None
    first, second = str(slot.get("type") or ""), str(end.get("type") or "")
    if slot_types_match(first, second):
        return end
    why = "have the same gender" if first == second else f"types '{first}' and '{second}' do not match"
    ctx.warn(f"the two Slot nodes {why}: the inner Slot is left out, as Webots refuses it", end.span)
    return None


def slot_types_match(first: str, second: str) -> bool:
    """Whether two Slots of these types pair (see `slot_end`)."""
    if not first or not second:
        return True
    if first[-1] in "+-":
        return first[:-1] == second[:-1] and first != second
    return first == second


def add_joint(builder: BodyBuilder, node: Node, body: mujoco.MjsBody, frame: Frame, robot: RobotEntry | None,
              dynamic: bool) -> None:
    """Add a Joint node: its endPoint as a child body, the MuJoCo joint(s) on it, and its devices."""
    ctx = builder.ctx
    end = node.get("endPoint")
    while isinstance(end, Node) and end.base_type == "Slot":  # a Slot passes its endPoint on, in the same frame
        end = slot_end(end, ctx)
    if isinstance(end, Node) and end.base_type == "SolidReference":
        ctx.warn("SolidReference endPoints (closed loops) are not supported by wbtc yet", end.span)
        return
    kind = node.base_type
    if body is ctx.spec.worldbody:
        _outside_solids(builder, node, end, body, frame, dynamic)
        return
    if not isinstance(end, Node) or not end.is_a("Solid"):
        if robot is not None:
            _without_end_point(builder, node, kind, body, frame, robot)
        return
    first = node.get("jointParameters")
    first_type = {"SliderJoint": "JointParameters", "BallJoint": "BallJointParameters"}.get(kind,
                                                                                            "HingeJointParameters")
    if isinstance(first, Node):
        ctx.unhonoured(first, _UNHONOURED)
    mark = len(robot.devices) if robot is not None else 0
    child = builder.add_solid(end, body, frame, robot, dynamic, joint_frame=frame)
    below = len(robot.devices) if robot is not None else 0
    count = _add_joints(builder, node, kind, child, frame, robot, first, first_type)
    if robot is not None:
        # Webots lists a joint's devices before its endPoint's devices, every axis's (`device`, then
        # `device2`, `device3`: WbHinge2Joint::devices) ahead of what the endPoint holds: the order of
        # getDeviceByIndex. They can only be made once the endPoint's body exists, so they are moved.
        own = robot.devices[below:below + count]
        del robot.devices[below:below + count]
        robot.devices[mark:mark] = own


def _outside_solids(builder: BodyBuilder, node: Node, end: object, body: mujoco.MjsBody, frame: Frame,
                    dynamic: bool) -> None:
    """A Joint with no Solid above it (at the top of the world, or in a top-level Pose or Group).

    Webots attaches no ODE joint then (WbBasicJoint::setJoint: no upper Solid): the endPoint is a
    Solid of its own, free when it has Physics. wbtc does the same, and says so.
    """
    ctx = builder.ctx
    ctx.warn(f"this {node.base_type} is not inside a Solid: Webots does not attach it, and its endPoint "
             "moves on its own (a joint belongs in the children of the Solid it turns against)", node.span,
             UNATTACHED_JOINT)
    if isinstance(end, Node) and end.is_a("Solid"):
        builder.add_solid(end, body, frame, None, dynamic)


def _without_end_point(builder: BodyBuilder, node: Node, kind: str, body: mujoco.MjsBody, frame: Frame,
                       robot: RobotEntry) -> None:
    """A Joint without endPoint: Webots keeps its devices (a motor turning nothing, a sensor reading it).

    An empty, nearly massless body stands in for the endPoint, so the devices exist, keep their
    indices and read the joint as Webots does; it has no geometry and pushes nothing.
    """
    ctx = builder.ctx
    first = node.get("jointParameters")
    first_type = {"SliderJoint": "JointParameters", "BallJoint": "BallJointParameters"}.get(kind,
                                                                                            "HingeJointParameters")
    child = body.add_body()
    child.name = ctx.unique("body", f"{robot.name}/{kind.lower()}_end")
    child.pos, child.quat = frame.pos, frame.quat
    child.explicitinertial = True
    child.mass = KINEMATIC_MASS
    child.inertia = [KINEMATIC_MASS * 1e-4] * 3
    _add_joints(builder, node, kind, child, frame, robot, first, first_type)


def _add_joints(builder: BodyBuilder, node: Node, kind: str, child: mujoco.MjsBody, frame: Frame,
                robot: RobotEntry | None, first: object, first_type: str) -> int:
    """The MuJoCo joint(s) of a Joint node on its endPoint's body, with their devices.

    Returns:
        How many devices the joint's axes (`device`, `device2`, `device3`) gave the robot.
    """
    ctx = builder.ctx
    child_pose = Frame(np.asarray(child.pos, dtype=float), np.asarray(child.quat, dtype=float), np.ones(3))
    anchor = frame.apply(np.asarray(param(first, first_type, "anchor") if kind != "SliderJoint" else [0, 0, 0],
                                    dtype=float))
    if kind == "SliderJoint":
        anchor = child_pose.pos  # a slider has no anchor: put the joint at the endPoint's origin
    else:
        raw = param(first, first_type, "anchor")
        ctx.hinge_anchors[child.name] = (float(raw[0]), float(raw[1]), float(raw[2]))
    if kind == "BallJoint" and not any(node.get(f) for f in ("device", "device2", "device3")):
        _make(child, node, ctx, mujoco.mjtJoint.mjJNT_BALL, child_pose, anchor, None, first, first_type)
        return 0
    axes: list[tuple[Node | None, str, str, np.ndarray]] = []
    if kind == "BallJoint":
        # Webots drives a ball joint through an Euler angular motor: the endPoint turns by
        # q(axis, θ1)·q(axis2, θ2)·q(axis3, θ3), axis2 = axis3 × axis (WbBallJoint). Three hinges
        # in one MuJoCo body compose their turns in that order, so they are that joint exactly.
        axis1, axis3 = ball_axes(node)
        second = node.get("jointParameters2")
        third = node.get("jointParameters3")
        axes += [(first, first_type, "device", axis1), (second, "JointParameters", "device2", np.cross(axis3, axis1)),
                 (third, "JointParameters", "device3", axis3)]
    else:
        axes.append((first, first_type, "device", np.asarray(param(first, first_type, "axis"), dtype=float)))
    if kind == "Hinge2Joint":
        # The second axis turns with the first: the endPoint is written at the first axis's
        # `position`, so at the reference pose the second axis is already turned by it (Webots' axis2).
        second = node.get("jointParameters2")
        turn = axis_angle_quat(axes[0][3], float(param(first, first_type, "position")))
        axes.append((second, "JointParameters", "device2",
                     quat_to_mat(turn) @ np.asarray(param(second, "JointParameters", "axis"), dtype=float)))
    joint_type = mujoco.mjtJoint.mjJNT_SLIDE if kind == "SliderJoint" else mujoco.mjtJoint.mjJNT_HINGE
    start = len(robot.devices) if robot is not None else 0
    for index, (params, params_type, device_field, local_axis) in enumerate(axes, start=1):
        axis = frame.rotate(local_axis)
        joint = _make(child, node, ctx, joint_type, child_pose, anchor, axis, params, params_type)
        if joint_type == mujoco.mjtJoint.mjJNT_HINGE and not ctx.options.ode_contacts:
            _round_wheels(child, np.asarray(joint.axis, dtype=float))
        position = float(param(params, params_type, "position"))
        for dev in node.get(device_field) or []:
            if isinstance(dev, Node) and robot is not None:
                device.add_joint_device(dev, joint, child, robot, ctx, position, index)
                if kind == "BallJoint" and index == 2:
                    _limit_middle_motor(robot.devices[-1], dev)
    return len(robot.devices) - start if robot is not None else 0


def _make(child: mujoco.MjsBody, node: Node, ctx: CompileContext, joint_type: mujoco.mjtJoint, child_pose: Frame,
          anchor: np.ndarray, axis: np.ndarray | None, params: Node | None, params_type: str) -> mujoco.MjsJoint:
    """One MuJoCo joint in the child body's frame."""
    joint = child.add_joint()
    joint.type = joint_type
    joint.name = ctx.unique("joint", child.name)
    joint.info = info(node)
    inverse = quat_conj(child_pose.quat)
    joint.pos = quat_rotate(inverse, anchor - child_pose.pos)
    if axis is not None:
        norm = np.linalg.norm(axis)
        joint.axis = quat_rotate(inverse, axis / norm if norm > 0 else np.array([0.0, 0.0, 1.0]))
    position = float(param(params, params_type, "position"))
    if joint_type != mujoco.mjtJoint.mjJNT_BALL:
        joint.ref = position  # the written pose is the pose at `position` (see module docstring)
    low, high = float(param(params, params_type, "minStop")), float(param(params, params_type, "maxStop"))
    if (low, high) != (0.0, 0.0) and low < high and joint_type != mujoco.mjtJoint.mjJNT_BALL:
        joint.limited = mujoco.mjtLimited.mjLIMITED_TRUE
        joint.range = [low, high]
        joint_stops.record(ctx, joint, params)
    # MuJoCo 4 takes polynomial coefficients; Webots' spring and damper are the linear terms.
    joint.stiffness = [float(param(params, params_type, "springConstant")), 0.0, 0.0]
    joint.damping = [float(param(params, params_type, "dampingConstant")), 0.0, 0.0]
    joint.frictionloss = float(param(params, params_type, "staticFriction"))
    return joint


def _round_wheels(body: mujoco.MjsBody, axis: np.ndarray) -> None:
    """Collide wheels (cylinders turning about their own axis) as thin ellipsoids.

    MuJoCo touches a cylinder lying on a plane at both rims and its soft friction settles between
    them when a robot turns: an e-puck scrubbing its cylinders on the spot loses a third of its turn
    rate. An ellipsoid with the wheel's radius and half width touches at one point, on the wheel's
    middle plane, so the robot turns as its wheel centres say. The mass properties stay the cylinder's.

    ODE (Webots' cylinder-plane collider) also touches at both rims, but its friction is hard Coulomb
    friction: when a differential drive turns, the outer rims grip and the inner ones slip, so Webots'
    robots turn as if their wheels touched at their outer rims (Webots' hinge_2_joint_damping robot
    spins at r·ω / 0.0575 = 0.696 rad/s where the middle planes give r·ω / 0.055 = 0.727; see that
    test's entry in tests/conformance/expected-failures.toml). With `CompileOptions.ode_contacts`
    (hard Coulomb friction, wbtc.compile.soft_contact) the wheels stay cylinders and touch at both
    rims, as in ODE: that robot then spins at 0.696 rad/s, Webots' figure.
    """
    for geom in body.geoms:
        if geom.group != COLLISION_GROUP or geom.type != mujoco.mjtGeom.mjGEOM_CYLINDER:
            continue
        geom_axis = quat_rotate(np.asarray(geom.quat, dtype=float), np.array([0.0, 0.0, 1.0]))
        if abs(float(np.dot(geom_axis, axis))) > 0.999:
            radius, half_height = float(geom.size[0]), float(geom.size[1])
            geom.type = mujoco.mjtGeom.mjGEOM_ELLIPSOID
            geom.size = [radius, radius, half_height]


def ball_axes(node: Node) -> tuple[np.ndarray, np.ndarray]:
    """A BallJoint's first and third axes, as WbBallJoint derives a missing one from the other.

    The first axis is `jointParameters2`'s and the third `jointParameters3`'s; without both, x and z.
    """
    second, third = node.get("jointParameters2"), node.get("jointParameters3")
    a = np.asarray(second.get("axis"), dtype=float) if isinstance(second, Node) else None
    c = np.asarray(third.get("axis"), dtype=float) if isinstance(third, Node) else None
    if a is None and c is None:
        return np.array([1.0, 0.0, 0.0]), np.array([0.0, 0.0, 1.0])
    if a is None:
        a = np.cross(c, [0.0, 0.0, 1.0])
        if not np.any(a):
            a = np.cross(c, [1.0, 0.0, 0.0])
    if c is None:
        c = np.cross(a, [1.0, 0.0, 0.0])
        if not np.any(c):
            c = np.cross(a, [0.0, 0.0, 1.0])
    return a, c


def _limit_middle_motor(entry: object, dev: Node) -> None:
    """The middle axis of a ball joint's Euler motor stays within ±π/2, as Webots limits its motor."""
    fields = getattr(entry, "fields", None)
    if dev.base_type != "RotationalMotor" or getattr(entry, "node", None) is not dev or fields is None:
        return  # not a motor, or one left out (a duplicate name)
    low, high = float(fields.get("minPosition", 0.0)), float(fields.get("maxPosition", 0.0))
    if low == high == 0.0:
        low, high = -math.pi / 2, math.pi / 2
    fields["minPosition"], fields["maxPosition"] = max(low, -math.pi / 2), min(high, math.pi / 2)

"""Webots' Track: a Solid whose belt surface moves, driven by the devices in its `device` field.

A Track compiles as the Solid it is (its body, bounding object and Physics, see `solid`), plus:

- its `device` list (LinearMotor, PositionSensor, Brake) as the robot's devices, right after the
  Track's place in the robot's device order and before its children's (Webots' `WbRobot::addDevices`
  takes a Track's devices when it meets the Track). They act on no joint: each `DeviceEntry` names the
  Track's body in `track`, and the runtime (`wbtc.runtime.tracks`) turns the motor's commands into the
  belt's surface velocity on every contact of the Track's collision geoms;
- each TrackWheel child as a body of its own without a joint (massless, visual only) at
  `(position.x, 0, position.y)` in the Track's frame, its hidden `rotation` applied, holding the
  wheel's children; the runtime turns it about the Track's y axis as the belt moves;
- `animatedGeometry` × `geometriesCount` as plates along the belt path round the TrackWheels
  (`track_belt`), which the runtime moves with the belt.

The table gets one `TrackEntry` per Track that has a motor or TrackWheels.

Not honoured yet: `textureAnimation` (MuJoCo cannot scroll a texture at run time); a Track outside a
Robot has no devices and its belt never moves (as in Webots, where devices need a robot).
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import TYPE_CHECKING

import mujoco
import numpy as np

from wbtc.compile.context import CompileContext, info
from wbtc.compile.frames import Frame, axis_angle_quat
from wbtc.compile.table import DeviceEntry, RobotEntry, plain_fields
from wbtc.compile.track_belt import BeltPath, add_plates
from wbtc.scene.model import Node

if TYPE_CHECKING:
    from wbtc.compile.solid import BodyBuilder

#: The devices a Track's `device` field accepts.
TRACK_DEVICES = ("LinearMotor", "PositionSensor", "Brake")
_UNHONOURED = frozenset({"textureAnimation"})


@dataclass
class TrackWheelEntry:
    """One TrackWheel: its body (turned by the runtime), radius and side of the belt.

    Attributes:
        body: the wheel's MuJoCo body (no joint, child of the Track's body).
        quat: the wheel's resting orientation in the Track's frame (its hidden `rotation`).
        radius: the wheel's radius (m).
        inner: whether the wheel is inside the belt (it turns the way the belt goes round).
    """

    body: str
    quat: np.ndarray
    radius: float
    inner: bool


@dataclass
class TrackEntry:
    """One Track of a robot.

    Attributes:
        body: the Track's MuJoCo body (its collision geoms are the belt's surface).
        robot: the robot's name.
        motor: the first LinearMotor of its `device` field (a device name), if any.
        brake: the first Brake, if any.
        sensors: its PositionSensors (device names); they read the belt's travelled distance.
        wheels: its TrackWheels.
        path: the belt path round the wheels (`track_belt.BeltPath`), when plates ride on it.
        plates: the bodies of the belt's plates (`animatedGeometry`), in order along the path.
    """

    body: str
    robot: str
    motor: str | None = None
    brake: str | None = None
    sensors: list[str] = field(default_factory=list)
    wheels: list[TrackWheelEntry] = field(default_factory=list)
    path: BeltPath | None = None
    plates: list[str] = field(default_factory=list)


def add_track(builder: BodyBuilder, node: Node, body: mujoco.MjsBody, robot: RobotEntry | None) -> TrackEntry | None:
    """The devices and TrackWheels of a Track whose body `body` has just been made (None: nothing to run).

    Args:
        builder: the body builder walking the scene.
        node: the Track.
        body: its MuJoCo body.
        robot: the robot holding it (None outside a robot: then it has no devices).
    """
    ctx = builder.ctx
    ctx.unhonoured(node, _UNHONOURED)
    entry = TrackEntry(body=body.name, robot=robot.name if robot is not None else "")
    if robot is not None:
        for device in node.get("device") or []:
            if isinstance(device, Node):
                _add_device(device, entry, body, robot, ctx)
        _pair(entry, robot)
    circles = []
    for child in node.get("children") or []:
        if isinstance(child, Node) and child.base_type == "TrackWheel":
            entry.wheels.append(_add_wheel(builder, child, body, robot))
            u, v = (float(c) for c in child.get("position"))
            circles.append((u, v, entry.wheels[-1].radius, entry.wheels[-1].inner))
    entry.path, entry.plates = add_plates(builder, node, body, robot, circles)
    if entry.motor is None and not entry.wheels and not entry.sensors and not entry.plates:
        return None
    ctx.table.tracks.append(entry)
    return entry


def _add_device(node: Node, track: TrackEntry, body: mujoco.MjsBody, robot: RobotEntry, ctx: CompileContext) -> None:
    """One LinearMotor, PositionSensor or Brake of the Track's `device` field."""
    kind = node.base_type
    if kind not in TRACK_DEVICES:
        ctx.warn(f"a Track's device field takes {', '.join(TRACK_DEVICES)}; this {kind} is left out", node.span)
        return
    name = str(node.get("name"))
    if robot.device(name) is not None:
        ctx.warn(f"robot {robot.name!r} already has a device named {name!r}; this one is not reachable", node.span)
        return
    robot.devices.append(DeviceEntry(name=name, type=kind, node=node, fields=plain_fields(node), body=body.name,
                                     track=body.name))
    # Webots drives the belt with the first motor and brakes it with the first brake (WbTrack::updateDevices).
    if kind == "LinearMotor" and track.motor is None:
        track.motor = name
    elif kind == "Brake" and track.brake is None:
        track.brake = name
    elif kind == "PositionSensor":
        track.sensors.append(name)


def _pair(track: TrackEntry, robot: RobotEntry) -> None:
    """Motor.getPositionSensor and PositionSensor.getMotor: the Track's first of each know each other."""
    if track.motor is None or not track.sensors:
        return
    motor, sensor = robot.device(track.motor), robot.device(track.sensors[0])
    if motor is not None and sensor is not None:
        motor.sensor, sensor.motor = sensor.name, motor.name


def _add_wheel(builder: BodyBuilder, wheel: Node, body: mujoco.MjsBody, robot: RobotEntry | None) -> TrackWheelEntry:
    """A TrackWheel as a jointless, massless body holding its children (the runtime turns it)."""
    ctx = builder.ctx
    x, y = (float(v) for v in wheel.get("position"))
    rotation = wheel.get("rotation")
    quat = axis_angle_quat((rotation[0], rotation[1], rotation[2]), rotation[3])
    child = body.add_body()
    child.name = ctx.unique("body", f"{body.name}/wheel")
    child.pos = [x, 0.0, y]  # the belt runs in the Track's xz plane, the wheels' axles along its y axis
    child.quat = quat
    child.info = info(wheel)
    child.explicitinertial = True
    child.mass = 0.0
    child.inertia = [0.0, 0.0, 0.0]
    builder.walk_children(wheel.get("children"), child, Frame.identity(), robot, True, wheel)
    return TrackWheelEntry(body=child.name, quat=np.asarray(quat, dtype=float), radius=float(wheel.get("radius")),
                           inner=bool(wheel.get("inner")))

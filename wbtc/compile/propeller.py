"""Propeller: its motor as a device with a center-of-thrust site, and its slow helix as visuals.

Webots turns a Propeller's RotationalMotor kinematically and pushes the Solid above the Propeller
with the thrust and torque of that rotation (see `wbtc.runtime.propeller`); the helices are moved by
Webots, not by the physics, and their mass does not weigh on the robot. So the compiler adds:

- a site at `centerOfThrust`, in the frame of the Propeller's parent, on the body of the Solid
  above (the runtime reads the shaft axis in that frame);
- the motor's DeviceEntry, with that site and the Propeller's `shaftAxis` (normalised; a zero axis
  becomes 0 1 0, as in Webots), `thrustConstants` and `torqueConstants`, and no joint or actuator;
- the slow helix's shapes as visual geoms of that body, where the helix Solid stands.

Not honoured yet: `fastHelix` and `fastHelixThreshold` (the slow helix is always drawn, still), the
helices' bounding objects (they do not collide).
"""

from __future__ import annotations

from typing import TYPE_CHECKING

import mujoco
import numpy as np

from wbtc.compile.context import info
from wbtc.compile.device import SITE_GROUP
from wbtc.compile.frames import Frame, axis_angle_quat
from wbtc.compile.table import DeviceEntry, RobotEntry, plain_fields
from wbtc.scene.model import Node

if TYPE_CHECKING:
    from wbtc.compile.solid import BodyBuilder

_UNHONOURED = frozenset({"fastHelix", "fastHelixThreshold"})


def add_propeller(builder: BodyBuilder, node: Node, body: mujoco.MjsBody, frame: Frame,
                  robot: RobotEntry | None) -> None:
    """Add a Propeller found under `body` at `frame` (its motor becomes a device of `robot`)."""
    ctx = builder.ctx
    ctx.unhonoured(node, _UNHONOURED)
    slow = node.get("slowHelix")
    if isinstance(slow, Node) and slow.is_a("Solid"):
        rotation = slow.get("rotation")
        helix = frame.compose(np.asarray(slow.get("translation"), dtype=float),
                              axis_angle_quat((rotation[0], rotation[1], rotation[2]), rotation[3]))
        for child in slow.get("children") or []:
            if isinstance(child, Node) and not child.is_a("Solid"):
                builder.walk(child, body, helix, None, False)  # shapes only: no devices, no bodies
    motor = node.get("device")
    if robot is None or not isinstance(motor, Node) or motor.base_type != "RotationalMotor":
        return
    name = str(motor.get("name"))
    if robot.device(name) is not None:
        ctx.warn(f"robot {robot.name!r} already has a device named {name!r}; this one is not reachable", motor.span)
        return
    axis = np.asarray(node.get("shaftAxis"), dtype=float)
    norm = float(np.linalg.norm(axis))
    if norm == 0.0:
        ctx.warn("'shaftAxis' cannot be zero; 0 1 0 is used, as in Webots", node.span)
        axis, norm = np.array([0.0, 1.0, 0.0]), 1.0
    center = frame.compose(np.asarray(node.get("centerOfThrust"), dtype=float), np.array([1.0, 0.0, 0.0, 0.0]))
    site = body.add_site()
    site.name = ctx.unique("site", f"{robot.name}/{name}")
    site.size = [0.002, 0, 0]
    site.group = SITE_GROUP
    site.info = info(node)
    site.pos, site.quat = center.pos, center.quat
    entry = DeviceEntry(name=name, type="RotationalMotor", node=motor, fields=plain_fields(motor), body=body.name,
                        site=site.name)
    entry.propeller = {"axis": (axis / norm).tolist(), "thrust": [float(v) for v in node.get("thrustConstants")],
                       "torque": [float(v) for v in node.get("torqueConstants")]}
    robot.devices.append(entry)

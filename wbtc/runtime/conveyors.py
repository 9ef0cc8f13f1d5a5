"""Webots' conveyor belts: the belt turns at its speed, its surface carries what lies on it.

Webots' ConveyorBelt PROTO runs Webots' own "conveyor_belt" controller (not part of a world's
project): it sets the motor "belt_motor" to `controllerArgs[0]` m/s (velocity control) and, when
`controllerArgs[1]` (the PROTO's `timer`) is positive, stops it once the simulated time reaches it.
The belt itself is a Track: its surface moves while its geometry stays.

wbtc's ConveyorBelt (protos/objects) puts its belt on a slider driven by "belt_motor"; every basic
step, before the motors act, this module does the controller's job for each robot of that PROTO and
puts the belt's slider back at its written position. The belt keeps the velocity its motor gives it,
so contacts carry the objects on it at the belt's speed (friction permitting), and its geometry
stays where it is (it is at most one step's travel ahead when sensors look).

Not honoured yet: the belt's texture animation; a supervisor restarting the belt after its timer.
"""

from __future__ import annotations

import math
from typing import Any

from wbtc.runtime.motors import Motor

#: The PROTO whose robots are conveyor belts, and their motor.
PROTO = "ConveyorBelt"
MOTOR = "belt_motor"


def _arguments(node: Any) -> tuple[float, float]:
    """(speed, timer) from the robot's controllerArgs, read as the conveyor_belt controller reads them."""
    values = []
    for item in list(node.get("controllerArgs") or [])[:2]:
        try:
            values.append(float(str(item)))
        except ValueError:
            values.append(0.0)
    values += [0.0] * (2 - len(values))
    return values[0], values[1]


def drive_belts(sim: Any) -> None:
    """Command each conveyor belt's motor for this step and put its slider back at its written position."""
    model, data = sim.model, sim.data
    for robot in sim.robots:
        instance = getattr(robot.entry.node, "proto", None)
        if instance is None or instance.name != PROTO:
            continue
        motor = next((m for m in robot.motors.values() if isinstance(m, Motor) and m.entry.name == MOTOR), None)
        if motor is None or not motor.entry.joint:
            continue
        speed, timer = _arguments(robot.entry.node)
        wanted = 0.0 if timer > 0 and sim.time >= timer else speed
        if math.isfinite(motor.target):
            motor.apply("setPosition", (math.inf,), sim.time_ms)
        if motor.velocity != wanted and motor.torque is None:
            motor.apply("setVelocity", (wanted,), sim.time_ms)
        joint = model.joint(motor.entry.joint)
        address = int(joint.qposadr[0])
        data.qpos[address] = model.qpos0[address]

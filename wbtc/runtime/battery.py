"""A Robot's battery: what its CPU and motors consume, its sensor, and the motors stopping when it is empty.

Webots (WbRobot::postPhysicsStep): a Robot whose `battery` field holds [energy (J), maximum (J),
recharge speed (W)] loses, after every physics step, (cpuConsumption + Σ devices' consumption) ×
the step's duration, never below 0; a motor consumes `consumptionFactor` × the torque (force) it
applied. When the energy reaches 0, Webots says "Battery is empty." and switches the robot's devices
off (WbRobot::powerOn): its motors give no torque any more, and its sensors stop refreshing
(`isPowerOn()` guards every sensor's refresh), so the controller keeps reading the values of the
last step the battery paid for in full. The step is drained before the sensors are read, so the
step that empties the battery is never seen (Simulation.step). The battery sensor
(`batterySensorEnable`) reads the energy left at each sampling period (0 once empty), -1 when the
`battery` field is empty.

Not honoured yet: recharging at a Charger (wbtc has no Charger node), devices other than motors
consuming energy (Webots' LEDs and others have no consumption of their own either).
"""

from __future__ import annotations

import math
import sys
from typing import Any

import mujoco

from wbtc.scene.model import Node


class Battery:
    """One robot's battery and its sensor."""

    def __init__(self, node: Node | None, motors: dict[int, Any]) -> None:
        """Read `battery` and `cpuConsumption` from the Robot node; meter its motors' effort."""
        field = node.get("battery") if node is not None else None
        values = [float(v) for v in field] if field is not None else []  # MFFloat: a numpy array
        self.energy = values[0] if values else -1.0  # -1: no battery (Webots' sensor reads -1)
        self.cpu = float(node.get("cpuConsumption")) if node is not None and node.get("cpuConsumption") is not None \
            else 10.0
        self.factors = {tag: float(m.entry.fields.get("consumptionFactor", 10.0)) for tag, m in motors.items()
                        if hasattr(m, "entry") and hasattr(m, "feedback") and hasattr(m, "metered")}
        self.powered = True
        self.period = 0
        self.due = math.inf
        self.value: float | None = None  # sampled since the last reply, else None
        if self.energy >= 0:
            for tag in self.factors:
                motors[tag].metered = True  # their mean effort over each step is kept (Motor.step_force)

    def carry_to(self, new: Battery, motors: dict[int, Any]) -> None:
        """Give a recompiled robot's battery this one's state (its motors are new objects)."""
        new.energy, new.powered = self.energy, self.powered
        new.period, new.due, new.value = self.period, self.due, self.value
        if not self.powered:
            for motor in motors.values():
                motor.available = 0.0

    def enable(self, period: int, now_ms: float) -> None:
        """`batterySensorEnable(p)`; 0 disables."""
        self.period = int(period)
        self.due = now_ms + self.period if self.period > 0 else math.inf

    def step(self, data: mujoco.MjData, motors: dict[int, Any], seconds: float, name: str) -> None:
        """Take one step's consumption off the energy; an empty battery switches the motors off."""
        if self.energy <= 0 or not self.powered:
            return
        consumption = self.cpu + sum(factor * abs(motors[tag].feedback(data)) for tag, factor in self.factors.items()
                                     if tag in motors)
        self.energy = max(self.energy - consumption * seconds, 0.0)
        if self.energy == 0.0:
            print(f"INFO: {name}: Battery is empty.", file=sys.stderr)
            self.powered = False
            for motor in motors.values():
                motor.available = 0.0
                if getattr(motor, "torque", None) is not None:
                    motor.torque = 0.0

    def sample(self, now_ms: float) -> None:
        """Read the energy when the sensor is due (after the step's consumption)."""
        if now_ms + 1e-9 >= self.due:
            self.value = self.energy
            self.due += self.period

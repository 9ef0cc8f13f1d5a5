"""``DifferentialWheels``: the controller class of Webots' old two-wheeled robot node (before R2018b).

wbtc gives such a robot wheel joints with motors "left wheel motor"/"right wheel motor" and sensors
"left wheel sensor"/"right wheel sensor" (``wbtc.scene.legacy_nodes``); this class drives them with the
old API: speeds in ``speedUnit`` rad/s, incremental encoders counting ``encoderResolution`` per radian
(they never move when ``encoderNoise`` is negative, Webots' rule), ``maxSpeed``/``speedUnit`` getters.
As Webots, ``setSpeed`` says on stderr when a speed goes over ``maxSpeed`` and still applies it.
"""

from __future__ import annotations

import math
import random
import sys

from . import _session
from .robot import Robot


class DifferentialWheels(Robot):
    """A DifferentialWheels robot (Webots <= R2018a); a Robot with wheel speeds and encoders."""

    def __init__(self) -> None:
        super().__init__()
        fields = _session.require().robot.get("differential_wheels") or {}
        if not fields:
            print("Error: this robot is not a DifferentialWheels: its DifferentialWheels functions do nothing.",
                  file=sys.stderr)
        self._unit = float(fields.get("speedUnit", 1.0))
        self._max_speed = float(fields.get("maxSpeed", 10.0))
        self._resolution = float(fields.get("encoderResolution", -1.0))
        self._noise = float(fields.get("encoderNoise", -1.0))
        names = (("left wheel motor", "left wheel sensor"), ("right wheel motor", "right wheel sensor"))
        self._motors = [self.devices.get(m) for m, _ in names]
        self._sensors = [self.devices.get(s) for _, s in names]
        self._speeds = [0.0, 0.0]
        self._encoders = [0.0, 0.0]
        self._angles = [0.0, 0.0]  # the wheel angles the encoders were last brought up to
        self._period = 0

    def setSpeed(self, left: float, right: float) -> None:
        """Wheel speeds in speedUnit rad/s, applied from the next step."""
        if math.isnan(left) or math.isnan(right):
            print("Error: wb_differential_wheels_set_speed(): invalid NaN value passed as argument.", file=sys.stderr)
            return
        if left * self._unit * 0.99999 > self._max_speed or right * self._unit * 0.99999 > self._max_speed:
            print(f"Error: wb_differential_wheels_set_speed({left:g},{right:g}) overflows maxSpeed/speedUnit: "
                  f"{self._max_speed:g}/{self._unit:g}={self._max_speed / self._unit:g}.", file=sys.stderr)
        self._speeds = [float(left), float(right)]
        for motor, speed in zip(self._motors, self._speeds, strict=True):
            if motor is not None:
                motor.setPosition(math.inf)
                motor.setVelocity(speed * self._unit)

    def getLeftSpeed(self) -> float:
        """The last left speed given to setSpeed."""
        return self._speeds[0]

    def getRightSpeed(self) -> float:
        """The last right speed given to setSpeed."""
        return self._speeds[1]

    def getMaxSpeed(self) -> float:
        """The robot's maxSpeed field."""
        return self._max_speed

    def getSpeedUnit(self) -> float:
        """The robot's speedUnit field."""
        return self._unit

    def enableEncoders(self, samplingPeriod: int) -> None:
        """Sample the encoders every ``samplingPeriod`` ms (the first values come one period later)."""
        if samplingPeriod < 0:
            print("Error: wb_differential_wheels_enable_encoders() called with negative sampling period.",
                  file=sys.stderr)
            return
        self._period = int(samplingPeriod)
        for sensor in self._sensors:
            if sensor is not None:
                sensor.enable(self._period) if self._period else sensor.disable()

    def disableEncoders(self) -> None:
        """Stop sampling the encoders."""
        self.enableEncoders(0)

    def getEncodersSamplingPeriod(self) -> int:
        """The encoders' sampling period (ms), 0 when disabled."""
        return self._period

    def _update(self) -> None:
        """Bring the encoders up to the wheels' last sampled angles."""
        for i, sensor in enumerate(self._sensors):
            angle = sensor.getValue() if sensor is not None else math.nan
            if math.isnan(angle):
                continue
            if self._noise >= 0:  # Webots: a negative encoderNoise means encoders that never move
                increment = angle - self._angles[i]
                if self._noise > 0:
                    increment *= 1.0 - self._noise + random.random() * 2.0 * self._noise
                self._encoders[i] += self._resolution * increment
            self._angles[i] = angle

    def getLeftEncoder(self) -> float:
        """The left encoder: encoderResolution per radian the wheel turned, since it was set."""
        self._update()
        return self._encoders[0]

    def getRightEncoder(self) -> float:
        """The right encoder: encoderResolution per radian the wheel turned, since it was set."""
        self._update()
        return self._encoders[1]

    def setEncoders(self, left: float, right: float) -> None:
        """Set both encoders' values (the wheels do not move)."""
        self._update()
        self._encoders = [float(left), float(right)]

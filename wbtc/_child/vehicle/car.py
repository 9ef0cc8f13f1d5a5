"""``Car``: Webots' car library (``wbu_car_*``) for robots built on the Car PROTO.

The car's geometry and engine come from the robot's customData (see the package docstring); its devices
are looked up by Webots' names. ``Car`` is a Supervisor, as Webots' Python ``Car``; ``Driver`` extends it
(as Webots' C++ ``Car`` and ``Driver`` share one library state), so a Driver has the Car getters too.
"""

from __future__ import annotations

import math
import sys

from controller import Supervisor

TYPE_CHECKING = False
if TYPE_CHECKING:
    from typing import Any

INDICATOR_PERIOD = 0.34  # s, Webots' default blinking period
WHEEL_MOTORS = ("right_front_wheel", "left_front_wheel", "right_rear_wheel", "left_rear_wheel")
WHEEL_SENSORS = ("right_front_sensor", "left_front_sensor", "right_rear_sensor", "left_rear_sensor")
WHEEL_BRAKES = ("right_front_brake", "left_front_brake", "right_rear_brake", "left_rear_brake")
LIGHTS = ("front_lights", "antifog_lights", "right_indicators", "left_indicators", "rear_lights",
          "backwards_lights", "brake_lights", "interior_right_indicators", "interior_left_indicators")
MIRRORS = (("rear_display", "rear_camera"), ("left_wing_display", "left_wing_camera"),
           ("right_wing_display", "right_wing_camera"))


def parse_custom_data(text: str) -> dict[str, Any] | None:
    """The car parameters the Car PROTO writes into customData, or None when the text does not hold them."""
    tokens = text.split()
    if len(tokens) < 20:
        return None
    try:
        numbers = [float(t) for t in tokens[:7]] + [0.0] + [float(t) for t in tokens[8:18]]
        gear_count, sound_length = int(tokens[18]), int(tokens[19])
        gears = [float(t) for t in tokens[20:20 + gear_count]]
    except ValueError:
        return None
    if len(tokens[7]) != 1 or len(gears) < gear_count:
        return None
    # The engine sound is the `sound_length` characters after the gear ratios (it may hold spaces).
    rest = text.lstrip()
    for _ in range(20 + gear_count):
        rest = rest.split(" ", 1)[1] if " " in rest else ""
        rest = rest.lstrip(" ")
    return {
        "wheelbase": numbers[0], "track_front": numbers[1], "track_rear": numbers[2],
        "front_wheel_radius": numbers[3], "rear_wheel_radius": numbers[4], "brake_coefficient": numbers[5],
        "damping": numbers[6], "engine_type": {"E": 1, "P": 2, "S": 3}.get(tokens[7], 0),
        "engine_max_torque": numbers[8], "engine_max_power": numbers[9], "engine_min_rpm": numbers[10],
        "engine_max_rpm": numbers[11], "engine_coefficients": numbers[12:15],
        "hybrid_power_split_ratio": numbers[15], "hybrid_power_split_rpm": numbers[16],
        "engine_sound_rpm_reference": numbers[17], "gear_number": gear_count, "gear_ratio": gears,
        "engine_sound": rest[:sound_length],
    }


class Car(Supervisor):
    """A robot built on Webots' Car PROTO: its geometry, wheels, lights and the car library's settings."""

    # types
    TRACTION = 0
    PROPULSION = 1
    FOUR_BY_FOUR = 2
    # engine types
    COMBUSTION_ENGINE = 0
    ELECTRIC_ENGINE = 1
    PARALLEL_HYBRID_ENGINE = 2
    POWER_SPLIT_HYBRID_ENGINE = 3
    # wheels
    WHEEL_FRONT_RIGHT = 0
    WHEEL_FRONT_LEFT = 1
    WHEEL_REAR_RIGHT = 2
    WHEEL_REAR_LEFT = 3

    def __init__(self) -> None:
        super().__init__()
        parameters = parse_custom_data(self.getCustomData())
        if parameters is None:
            print("Error: Only nodes based on the 'Car' node can use the car library.", file=sys.stderr)
            sys.exit(-1)
        if parameters["gear_number"] < 2:
            print("Error: Any car should have a minimum of two gear ratios.", file=sys.stderr)
            sys.exit(-1)
        self._car = parameters
        self._indicator_period = INDICATOR_PERIOD
        self._right_angle = 0.0
        self._left_angle = 0.0
        self._limited_slip_differential = True
        self._indicator_auto_disabling = True
        self._speeds = [0.0, 0.0, 0.0, 0.0]
        step = int(self.getBasicTimeStep())
        devices = self.devices
        self._steering_motors = [devices.get("right_steer"), devices.get("left_steer")]
        self._steering_sensors = [devices.get("right_steer_sensor"), devices.get("left_steer_sensor")]
        if None in self._steering_motors:
            print("Error: Any car should have 'right_steer' and 'left_steer' motors.", file=sys.stderr)
            sys.exit(-1)
        if None in self._steering_sensors:
            print("Error: Any car should have 'right_steer_sensor' and 'left_steer_sensor' position sensors.",
                  file=sys.stderr)
            sys.exit(-1)
        for sensor in self._steering_sensors:
            sensor.enable(step)
        self._wheels = [devices.get(name) for name in WHEEL_MOTORS]
        self._lights = [devices.get(name) for name in LIGHTS]
        self._steering_wheel = devices.get("steering_wheel_motor")
        self._indicator_lever = devices.get("indicator_lever_motor")
        self._wiper_motors = [devices.get("right_wiper_motor"), devices.get("left_wiper_motor")]
        self._wiper_sensor = devices.get("wiper_sensor")
        self._needles = [devices.get("rpm_needle_motor"), devices.get("speed_needle_motor")]
        if self._wiper_sensor is not None:
            self._wiper_sensor.enable(step)
        front, rear = self._wheels[0] and self._wheels[1], self._wheels[2] and self._wheels[3]
        if front and rear:
            self._type = Car.FOUR_BY_FOUR
        elif front:
            self._type = Car.TRACTION
        elif rear:
            self._type = Car.PROPULSION
        else:
            print("Error: this car does not have the required motors", file=sys.stderr)
            sys.exit(-1)
        self._sensors = [devices.get(name) for name in WHEEL_SENSORS]
        if None in self._sensors:
            print("Error: this car does not have the required position sensors", file=sys.stderr)
            sys.exit(-1)
        self._brakes = [devices.get(name) for name in WHEEL_BRAKES]
        if None in self._brakes:
            print("Error: this car does not have the required brake devices", file=sys.stderr)
            sys.exit(-1)
        for display_name, camera_name in MIRRORS:
            display, camera = devices.get(display_name), devices.get(camera_name)
            if display is not None and camera is not None and \
                    (display.getWidth(), display.getHeight()) == (camera.getWidth(), camera.getHeight()):
                period = step
                while period < 40:  # at most 25 Hz
                    period += step
                camera.enable(period)
                display.attachCamera(camera)
        for motor in self._driven():
            motor.setPosition(math.inf)
            motor.setVelocity(0.0)

    # -- library internals ----------------------------------------------------------------------------------
    def _driven(self) -> list[Any]:
        """The wheel motors the car's type drives (front, rear or both pairs)."""
        pairs = {Car.TRACTION: (0, 1), Car.PROPULSION: (2, 3), Car.FOUR_BY_FOUR: (0, 1, 2, 3)}[self._type]
        return [self._wheels[i] for i in pairs]

    def _set_light(self, name: str, state: bool) -> None:
        """Switch a light on or off when the car has it; indicators also switch their interior twins."""
        index = LIGHTS.index(name)
        if self._lights[index] is not None:
            self._lights[index].set(1 if state else 0)
        twin = {"right_indicators": "interior_right_indicators",
                "left_indicators": "interior_left_indicators"}.get(name)
        if twin is not None and self._lights[LIGHTS.index(twin)] is not None:
            self._lights[LIGHTS.index(twin)].set(1 if state else 0)

    def _light_on(self, name: str) -> bool:
        led = self._lights[LIGHTS.index(name)]
        return led is not None and led.get() != 0

    # -- Car API --------------------------------------------------------------------------------------------
    def getType(self) -> int:
        """TRACTION, PROPULSION or FOUR_BY_FOUR: which wheels have motors."""
        return self._type

    def getEngineType(self) -> int:
        """COMBUSTION_ENGINE, ELECTRIC_ENGINE, PARALLEL_HYBRID_ENGINE or POWER_SPLIT_HYBRID_ENGINE."""
        return self._car["engine_type"]

    def getWheelbase(self) -> float:
        """Distance between the front and rear axles (m)."""
        return self._car["wheelbase"]

    def getTrackFront(self) -> float:
        """Distance between the front wheels (m)."""
        return self._car["track_front"]

    def getTrackRear(self) -> float:
        """Distance between the rear wheels (m)."""
        return self._car["track_rear"]

    def getFrontWheelRadius(self) -> float:
        """Radius of the front wheels (m; -1 when the car could not tell)."""
        return self._car["front_wheel_radius"]

    def getRearWheelRadius(self) -> float:
        """Radius of the rear wheels (m; -1 when the car could not tell)."""
        return self._car["rear_wheel_radius"]

    def getIndicatorPeriod(self) -> float:
        """The indicators' blinking period (s)."""
        return self._indicator_period

    def setIndicatorPeriod(self, period: float) -> None:
        """Set the indicators' blinking period (s)."""
        self._indicator_period = float(period)

    def getBackwardsLights(self) -> bool:
        """Whether the backwards lights are on."""
        return self._light_on("backwards_lights")

    def getBrakeLights(self) -> bool:
        """Whether the brake lights are on."""
        return self._light_on("brake_lights")

    def getWheelEncoder(self, wheel_index: int) -> float:
        """The angle (rad) a wheel turned (WHEEL_FRONT_RIGHT ... WHEEL_REAR_LEFT); enables its sensor if needed."""
        if not 0 <= wheel_index < 4:
            print("Warning: maximum wheel index is 4.", file=sys.stderr)
            return 0.0
        sensor = self._sensors[wheel_index]
        if sensor.getSamplingPeriod() == 0:
            sensor.enable(int(self.getBasicTimeStep()))
        return sensor.getValue()

    def getWheelSpeed(self, wheel_index: int) -> float:
        """A wheel's rotational speed (rad/s), as the driver library last measured it."""
        if not 0 <= wheel_index < 4:
            print("Warning: maximum wheel index is 4.", file=sys.stderr)
            return 0.0
        return self._speeds[wheel_index]

    def getRightSteeringAngle(self) -> float:
        """The right front wheel's steering angle (rad, read by its sensor)."""
        return self._steering_sensors[0].getValue()

    def getLeftSteeringAngle(self) -> float:
        """The left front wheel's steering angle (rad, read by its sensor)."""
        return self._steering_sensors[1].getValue()

    def setRightSteeringAngle(self, angle: float) -> None:
        """Steer the right front wheel alone (rad)."""
        self._steering_motors[0].setPosition(angle)

    def setLeftSteeringAngle(self, angle: float) -> None:
        """Steer the left front wheel alone (rad)."""
        self._steering_motors[1].setPosition(angle)

    def enableLimitedSlipDifferential(self, enable: bool) -> None:
        """Use (or not) the limited slip differential in torque control (on by default)."""
        self._limited_slip_differential = bool(enable)

    def enableIndicatorAutoDisabling(self, enable: bool) -> None:
        """Switch the indicator off (or not) when the wheel turns back (on by default)."""
        self._indicator_auto_disabling = bool(enable)

    # -- snake_case properties ------------------------------------------------------------------------------
    @property
    def type(self) -> int:
        """The car's type."""
        return self.getType()

    @property
    def engine_type(self) -> int:
        """The engine's type."""
        return self.getEngineType()

    @property
    def wheelbase(self) -> float:
        """The wheelbase (m)."""
        return self.getWheelbase()

    @property
    def track_front(self) -> float:
        """The front track (m)."""
        return self.getTrackFront()

    @property
    def track_rear(self) -> float:
        """The rear track (m)."""
        return self.getTrackRear()

    @property
    def front_wheel_radius(self) -> float:
        """The front wheels' radius (m)."""
        return self.getFrontWheelRadius()

    @property
    def rear_wheel_radius(self) -> float:
        """The rear wheels' radius (m)."""
        return self.getRearWheelRadius()

    @property
    def indicator_period(self) -> float:
        """The indicators' blinking period (s)."""
        return self.getIndicatorPeriod()

    @indicator_period.setter
    def indicator_period(self, period: float) -> None:
        self.setIndicatorPeriod(period)

    @property
    def backwards_lights(self) -> bool:
        """Whether the backwards lights are on."""
        return self.getBackwardsLights()

    @property
    def brake_lights(self) -> bool:
        """Whether the brake lights are on."""
        return self.getBrakeLights()

    @property
    def right_steering_angle(self) -> float:
        """The right front wheel's steering angle (rad)."""
        return self.getRightSteeringAngle()

    @right_steering_angle.setter
    def right_steering_angle(self, angle: float) -> None:
        self.setRightSteeringAngle(angle)

    @property
    def left_steering_angle(self) -> float:
        """The left front wheel's steering angle (rad)."""
        return self.getLeftSteeringAngle()

    @left_steering_angle.setter
    def left_steering_angle(self, angle: float) -> None:
        self.setLeftSteeringAngle(angle)
